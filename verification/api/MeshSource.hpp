#pragma once
// Where a command's mesh comes from, in the words of `vorodg mesh` and `vorodg solve`: a family
// with its domain, size, perturbation, seed and regularization, or a file. The options (cli/)
// and the Python module's `generate_mesh` fill the same struct and get the same checks and
// messages, which name the options (--d, --h, --domain).
#include <cstdint>
#include <string>

#include "core/meshgen/MeshFamily.hpp"

namespace vorodg {

struct MeshSourceOptions {
  std::string family = std::string(family_name(MeshSpec{}.family));
  std::string domain = "0,0,4,1";
  double d = 0.0;  // rcp, tri
  double h = 0.0;  // hex, perturbed-hex, quad
  double r = MeshSpec{}.perturbation;
  std::uint64_t seed = MeshSpec{}.seed;
  double regularize = MeshSpec{}.regularization;
  std::string file;  // --mesh FILE.vtu (solve only)
};

/// The MeshSpec the options describe (family `file` when o.file is set). `domain_given` says
/// whether --domain was on the command line (an imported mesh otherwise keeps its own). Throws
/// InputError naming the option that does not fit the family.
MeshSpec mesh_spec(const MeshSourceOptions& o, bool domain_given);

}  // namespace vorodg
