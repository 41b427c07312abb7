#pragma once
// `vorodg run SCENE.json -o DIR`: runs a study scene (resuming what DIR already holds) and
// writes its report; `vorodg run --list` lists the shipped scenes, `vorodg run --keys KIND` the
// keys of a study kind.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <string>

#include "verification/api/SceneStudy.hpp"

namespace vorodg {

/// `run`'s options: a scene study's, and the two that list instead of running.
struct RunCommandOptions : SceneStudyOptions {
  bool list = false;
  std::string keys;  // a study kind: print its keys and stop
};

CLI::App* add_run_command(CLI::App& app, RunCommandOptions& options);
int run_run_command(const RunCommandOptions& options, const CLI::App& command);

}  // namespace vorodg
