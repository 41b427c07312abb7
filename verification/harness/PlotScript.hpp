#pragma once
// The pictures of a study are drawn by a Python script of scripts/ (Debian's python3 and
// matplotlib) reading the study's output folder. A missing interpreter, script or library is a
// note on stderr, not an error: every number is in the report files already.
#include <filesystem>
#include <string>

namespace vorodg {

/// Runs scripts/<script> on `out`; returns false (after the note) if it could not.
bool draw_plots(const std::string& script, const std::filesystem::path& out);

}  // namespace vorodg
