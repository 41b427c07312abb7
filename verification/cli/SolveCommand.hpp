#pragma once
// `vorodg solve`: one problem on one mesh (generated or read), one formulation; writes the
// result as .vtu (displacement, exact displacement, error; per cell mean stress, von Mises and
// error densities) and the metrics as JSON.
#include <CLI/CLI.hpp>
#include <string>

#include "verification/SolveRun.hpp"
#include "verification/cli/CliSupport.hpp"

namespace vorodg {

struct SolveCommandOptions {
  MeshSourceOptions mesh;
  SolveSettings settings;
  std::string plane = "stress";
  bool no_correction = false;
  std::string ordering = "node-metis";
  std::string output;
  std::string metrics;
};

CLI::App* add_solve_command(CLI::App& app, SolveCommandOptions& options);
int run_solve_command(const SolveCommandOptions& options, const CLI::App& command);

}  // namespace vorodg
