#pragma once
// Outputs are written atomically: to a temporary file beside the target, renamed into place only
// once complete, so a stopped run never leaves a half-written file under the real name.
#include <filesystem>
#include <string>

namespace vorodg {

/// Writes `contents` to `path` atomically. Throws InputError naming the path if the folder does
/// not exist or cannot be written.
void write_file_atomically(const std::filesystem::path& path, const std::string& contents);

/// Reads a whole file; throws InputError naming the path if it cannot be read.
std::string read_file(const std::filesystem::path& path);

}  // namespace vorodg
