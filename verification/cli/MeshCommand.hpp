#pragma once
// `vorodg mesh`: generate a mesh of any family (or check one from a file), write it as .vtu and
// report its statistics as JSON.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

#include "verification/cli/CliSupport.hpp"

namespace vorodg {

struct MeshCommandOptions {
  MeshSourceOptions mesh;
  VtuOutputOptions output;
  std::string stats;
  std::string check;
};

/// Registers the `mesh` subcommand; `run` is called after a successful parse.
CLI::App* add_mesh_command(CLI::App& app, MeshCommandOptions& options);
int run_mesh_command(const MeshCommandOptions& options, const CLI::App& command);

}  // namespace vorodg
