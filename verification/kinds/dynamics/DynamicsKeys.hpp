#pragma once
// The key table of a dynamics or fragmentation scene (DynamicsKeys.cpp): every key's name, type,
// default, range and one-line doc. The reader (DynamicsScene.cpp) takes the fixed defaults and
// the numeric bounds from here; defaults that depend on the problem are stated in words and
// computed by the reader. docs/scenes.md lists the same table (a test checks every key).
#include <string>

#include "core/schema/SceneKeys.hpp"

namespace vorodg {

const KeyTable& dynamics_scene_keys();
/// The key of that full name; throws std::out_of_range for an unknown one (a programming error).
const SceneKey& dynamics_key(const std::string& name);

}  // namespace vorodg
