#pragma once
// The scene keys of the cohesive law and of the Mohr-Coulomb insertion criterion, as every kind
// with cracks spells them; the kinds differ only in their defaults.
#include <string>
#include <vector>

#include "core/schema/SceneKeys.hpp"

namespace vorodg {

/// The defaults of the cohesive keys where the kinds differ.
struct CohesiveDefaults {
  std::string strength, fracture_energy, initial_stiffness, friction;
  std::string initial_stiffness_use;  // when K0 applies, for its doc
  std::string scope;                  // "fragmentation: ", or "" where every scene has them
};

/// cohesive.law (the registered softening laws, the first the default), .strength,
/// .fracture_energy, .shear_factor, .initial_stiffness, and criterion.cohesion, .friction,
/// .tensile_cutoff.
std::vector<SceneKey> cohesive_keys(const CohesiveDefaults& defaults);

}  // namespace vorodg
