#pragma once
// Pieces every subcommand shares: where its mesh comes from (a family and its parameters, or a
// file), the echo of its options (the printed line reproduces the run), and the check that
// output folders exist before any work starts.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <map>
#include <string>

#include "core/io/VtuMesh.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "verification/api/MeshSource.hpp"

namespace vorodg {

/// Where a command writes its .vtu (`-o FILE`) and how (`--ascii`; compressed binary otherwise).
struct VtuOutputOptions {
  std::string path;
  bool ascii = false;
  VtuEncoding encoding() const { return ascii ? VtuEncoding::ascii : VtuEncoding::binary_zlib; }
};
/// Registers -o/--output (`what` says what is written) and --ascii.
void add_vtu_output_options(CLI::App& command, VtuOutputOptions& o, const std::string& what);

/// Refuses a number option's text unless it is a finite number ("nan", "inf", "1e400", "abc"
/// are refused while parsing, before anything is echoed or computed).
CLI::Validator finite_number();
/// Refuses an unsigned option's text unless it is an integer in 0..2^64-1 (CLI11 would wrap
/// "-1" and saturate "99999999999999999999").
CLI::Validator unsigned_integer();

/// Registers --family, --domain, --d, --h, --r, --seed, --regularize on a subcommand.
void add_mesh_source_options(CLI::App& command, MeshSourceOptions& o);
/// Prints "# <prefix> --option value ..." with every option's value or default.
void echo_options(const std::string& prefix, const CLI::App& command,
                  const std::map<std::string, std::string>& resolved = {});
/// Throws InputError if the folder of `path` is not an existing folder (nothing to do for an
/// empty path).
void check_output_folder(const std::string& path, const char* option);

}  // namespace vorodg
