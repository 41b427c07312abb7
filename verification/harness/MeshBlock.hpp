#pragma once
// A mesh block of a scene: one mesh family (or a list of mesh files) with its levels, its
// realizations per level (one count, or one per level) and its base seed. Every study kind reads
// its `meshes` through read_mesh (keys: CommonKeys' mesh_keys) and runs one unit of work per
// (block, level, realization) (EnsembleRun).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/geometry/Rectangle.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/schema/SceneObject.hpp"
#include "verification/model/Choices.hpp"

namespace vorodg {

struct SceneMesh {
  std::string label;  // default: the family name
  MeshFamily family = MeshFamily::rcp;
  std::vector<double> sizes;  // d (rcp, tri) or h (hex, perturbed-hex, quad), coarse to fine
  /// file: one .vtu per level, coarse to fine, resolved against the scene's folder. Their sizes
  /// are the meshes' h_avg, so that every study counts levels by `sizes`.
  std::vector<std::filesystem::path> files;
  int realizations = 1;
  /// realizations_per_level: a count per level instead (a statistical campaign affords many
  /// coarse runs and few fine ones); empty: `realizations` at every level.
  std::vector<int> realizations_per_level;
  std::uint64_t seed = MeshSpec{}.seed;
  double perturbation = MeshSpec{}.perturbation;
  double regularization = MeshSpec{}.regularization;
  bool symmetric = false;   // rcp: mirrored about the vertical mid-line
  bool notch_only = false;  // symmetric "notch": mirrored along the notch and at the top only

  /// The realizations of `level`.
  int realizations_at(int level) const {
    return realizations_per_level.empty() ? realizations : realizations_per_level.at(level);
  }
  /// What the generator needs for one realization of one level.
  MeshSpec spec(const Rectangle& domain, int level, std::uint64_t realization_seed) const;
};

/// Reads one mesh block (files are read and validated now); throws InputError naming the key.
SceneMesh read_mesh(SceneObject& m, const Rectangle& domain);

}  // namespace vorodg
