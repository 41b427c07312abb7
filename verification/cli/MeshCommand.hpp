#pragma once
// `vorodg mesh`: generate a mesh of any family (or check one from a file), write it as .vtu and
// report its statistics as JSON.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>

namespace vorodg {

struct MeshCommandOptions {
  std::string family = "rcp";
  std::string domain = "0,0,4,1";
  double d = 0.0;  // rcp, tri
  double h = 0.0;  // hex, perturbed-hex, quad
  double r = 0.3;
  std::uint64_t seed = 1;
  double regularize = 0.1;
  std::string output;
  std::string stats;
  std::string check;
};

/// Registers the `mesh` subcommand; `run` is called after a successful parse.
CLI::App* add_mesh_command(CLI::App& app, MeshCommandOptions& options);
int run_mesh_command(const MeshCommandOptions& options, const CLI::App& command);

}  // namespace vorodg
