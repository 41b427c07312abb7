#pragma once
// The scene keys of a random material field (core/random/MaterialField, docs/statistics.md), as
// every kind that varies its material spells them, and their reader: a field in space whose
// realization i is the same on every mesh level.
#include <vector>

#include "core/random/MaterialField.hpp"
#include "core/schema/SceneKeyReader.hpp"
#include "core/schema/SceneKeys.hpp"

namespace vorodg {

/// material.field, .field_length, .field_smoothness, .field_marginal, .field_amplitude,
/// .field_shape, .field_spacing, .field_seed.
std::vector<SceneKey> material_field_keys();

/// Reads them from the scene's `material` object (field none: not enabled, the other keys
/// echoed at their defaults). A field without field_length is refused in one line.
MaterialField read_material_field(SceneKeyReader& reader, SceneObject& material);

}  // namespace vorodg
