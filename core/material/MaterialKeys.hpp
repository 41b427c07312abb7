#pragma once
// The scene keys of the elastic material, as every kind spells them: material.E, material.nu and
// material.plane, each kind giving its own defaults of E and nu.
#include <string>
#include <vector>

#include "core/schema/SceneKeys.hpp"

namespace vorodg {

/// material.E, material.nu, material.plane with the kind's defaults of E and nu (as text).
std::vector<SceneKey> elastic_keys(const std::string& E, const std::string& nu);

}  // namespace vorodg
