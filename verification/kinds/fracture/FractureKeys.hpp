#pragma once
// The key table of a fracture scene (FractureKeys.cpp; docs/scenes.md "Fracture studies").
#include "core/schema/SceneKeys.hpp"

namespace vorodg {

const KeyTable& fracture_scene_keys();

}  // namespace vorodg
