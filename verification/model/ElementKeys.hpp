#pragma once
// The scene keys of the element family, as every kind spells them, with the element names the
// program knows (Choices).
#include <vector>

#include "core/schema/SceneKeys.hpp"

namespace vorodg {

/// element, vem_stabilization: the element family of every run.
std::vector<SceneKey> element_keys();

}  // namespace vorodg
