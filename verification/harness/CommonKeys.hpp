#pragma once
// The scene keys of the harness that more than one kind has: the scene's name and description,
// the mesh blocks and the variants. Each is spelled, bounded and documented here once; a kind's
// table splices them in. The physical quantities several kinds share bring their rows from
// their own libraries: the elastic material (core/material/MaterialKeys), the cohesive law and
// the insertion criterion (fracture/CohesiveKeys), and the element (model/ElementKeys).
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
/// checkpoint.wall_seconds and checkpoint.steps: how often a long run checkpoints
/// (RunCheckpoints).
std::vector<SceneKey> checkpoint_keys();

}  // namespace vorodg
