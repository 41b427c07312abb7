#pragma once
// The key tables of the static study kinds: convergence, penalty-sweep, patch-suite and trade-off
// share one; extremes adds its sweeps. The settings of a solve (material, formulations[],
// outputs) come from the settings schema (SettingsSchema), the mesh blocks from the keys every
// kind shares (CommonKeys); the rest (the study, its problems and domain, the patch tolerance,
// the trade-off's knobs, the sweeps) are written here, their defaults taken from the structs
// the reader fills. The readers (Scene.cpp, SceneSweeps.cpp, TradeoffSettings.cpp) take the
// bounds of these keys from here; docs/scenes.md lists the same rows.
#include <string>

#include "core/schema/SceneKeys.hpp"

namespace vorodg {

/// The keys of a convergence, penalty-sweep, patch-suite or trade-off scene.
const KeyTable& static_scene_table();
/// The same with sweeps[] (an extremes scene).
const KeyTable& extremes_scene_table();
/// Their rows, for the registry of kinds.
std::vector<SceneKey> static_scene_keys();
std::vector<SceneKey> extremes_scene_keys();
/// A row of either by its full name ("tradeoff.min_seconds"); throws std::out_of_range for
/// another (a programming error).
const SceneKey& static_key(const std::string& name);

}  // namespace vorodg
