#include "verification/api/MeshSource.hpp"

#include "core/geometry/Rectangle.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"

namespace vorodg {
namespace {

/// The size option a family takes, checked against what was given.
double family_size(MeshFamily family, const MeshSourceOptions& o) {
  const bool seeded = family == MeshFamily::rcp || family == MeshFamily::tri;
  const std::string name(family_name(family));
  if (seeded) {
    if (o.h != 0.0) throw InputError("--h: family " + name + " takes --d (minimum seed distance)");
    if (!(o.d > 0.0))
      throw InputError("--d = " + fmt(o.d) + ": family " + name +
                       " needs a minimum seed distance d > 0");
    return o.d;
  }
  if (o.d != 0.0) throw InputError("--d: family " + name + " takes --h (cell size)");
  if (!(o.h > 0.0))
    throw InputError("--h = " + fmt(o.h) + ": family " + name + " needs a cell size h > 0");
  return o.h;
}

}  // namespace

MeshSpec mesh_spec(const MeshSourceOptions& o, bool domain_given) {
  MeshSpec spec;
  try {
    spec.domain = Rectangle::parse(o.domain);
  } catch (const InputError& e) {
    throw InputError(std::string("--domain: ") + e.what());
  }
  spec.domain_given = domain_given;
  if (!o.file.empty()) {
    spec.family = MeshFamily::file;
    spec.path = o.file;
    return spec;
  }
  spec.family = parse_family(o.family);
  if (spec.family == MeshFamily::file)
    throw InputError("--family file: give the mesh as --mesh FILE");
  spec.size = family_size(spec.family, o);
  spec.seed = o.seed;
  spec.perturbation = o.r;
  spec.regularization = o.regularize;
  return spec;
}

}  // namespace vorodg
