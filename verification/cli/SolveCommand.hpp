#pragma once
// `vorodg solve`: one problem on one mesh (generated or read), one formulation; writes the
// result as .vtu (verification/cli/ResultFile.hpp) and the metrics as JSON. Its settings are
// the schema's (verification/solve/SettingsSchema.hpp).
#include <CLI/CLI.hpp>
#include <string>

#include "verification/cli/CliSupport.hpp"
#include "verification/cli/SettingOptions.hpp"

namespace vorodg {

struct SolveCommandOptions {
  MeshSourceOptions mesh;
  SettingOptions settings;
  VtuOutputOptions output;
  std::string metrics;
};

CLI::App* add_solve_command(CLI::App& app, SolveCommandOptions& options);
int run_solve_command(const SolveCommandOptions& options, const CLI::App& command);

}  // namespace vorodg
