#pragma once
// The scene keys more than one kind has: the scene's name and description, the mesh blocks and
// the variants, and the physical quantities: the elastic material, the element, the cohesive
// law and the Mohr-Coulomb criterion. Each is spelled, bounded and
// documented here once; a kind's table splices them in with its own defaults, so that the same
// quantity has the same key in every kind.
#include <string>
#include <vector>

#include "core/schema/SceneKeys.hpp"

namespace vorodg {

/// name, description: what every scene is called and says of itself.
std::vector<SceneKey> naming_keys();
/// meshes[] and the keys of a mesh block, as every kind reads them (read_mesh).
std::vector<SceneKey> mesh_keys();
/// One of them by its full name ("meshes[].seed"); throws std::out_of_range for another.
const SceneKey& mesh_key(const std::string& name);
/// variants[]: studies side by side, each merged over the top-level keys.
SceneKey variants_key();

/// material.E, material.nu, material.plane.
std::vector<SceneKey> elastic_keys(const std::string& E, const std::string& nu);

/// element, vem_stabilization: the element family of every run.
std::vector<SceneKey> element_keys();

/// The defaults of the cohesive keys where the kinds differ.
struct CohesiveDefaults {
  std::string strength, fracture_energy, initial_stiffness, friction;
  std::string initial_stiffness_use;  // when K0 applies, for its doc
  std::string scope;                  // "fragmentation: ", or "" where every scene has them
  /// The softening laws a scene may name, the first the default (from fracture/, which the
  /// kinds include and the harness does not).
  std::string law_default, law_names;
};

/// cohesive.law, .strength, .fracture_energy, .shear_factor, .initial_stiffness, and
/// criterion.cohesion, .friction, .tensile_cutoff.
std::vector<SceneKey> cohesive_keys(const CohesiveDefaults& defaults);

}  // namespace vorodg
