#pragma once
// `vorodg run SCENE.json -o DIR`: runs a study scene (resuming what DIR already holds) and
// writes its report; `vorodg run --list` lists the shipped scenes, `vorodg run --keys KIND` the
// keys of a study kind.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>

namespace vorodg {

struct RunCommandOptions {
  std::string scene;
  std::string out;
  int threads = 2;
  bool list = false;
  std::string keys;  // a study kind: print its keys and stop
  bool no_plots = false;
  bool quiet = false;
  bool force = false;  // dynamics: allow time.safety >= 1
  std::string shard;   // "K/N": run the tasks whose place is K modulo N (a job array)
};

CLI::App* add_run_command(CLI::App& app, RunCommandOptions& options);
int run_run_command(const RunCommandOptions& options, const CLI::App& command);
/// The study of `options` without the echo of the command line (what `merge` reuses).
int run_study_scene(const RunCommandOptions& options);
/// A scene file, or the shipped scene of that name; throws InputError if neither exists.
std::filesystem::path resolve_scene(const std::string& name);

/// The file in an output folder that names the scene it was run from (for `vorodg merge`).
inline constexpr const char* kRunInfoFile = "run.json";

}  // namespace vorodg
