#pragma once
// One run of a fracture or fragmentation scene, run as its study runs it (the same files under
// the output folder, the same record), for a caller that wants to watch it: the Python module's
// fracture_path and fragmentation_run. The scene's part is chosen by its variant's label, the
// run by its place among the mesh runs or by its id ("rcp-L0-R2").
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <variant>

#include "core/mesh/PolygonMesh.hpp"
#include "dg/QuasiStaticPath.hpp"
#include "dynamics/ExplicitSimulation.hpp"

namespace vorodg {

/// Where to find a scene's run, and what to call it.
struct SceneRunChoice {
  std::string text, source;            // the scene, and what messages call it
  std::optional<std::string> variant;  // the part's label; none: the scene (if it has no parts)
  std::variant<int, std::string> run;  // its place among the mesh runs, or its id
  std::filesystem::path output;        // the folder its files go to
};

/// A finished run: its results.jsonl line and the mesh it ran on.
struct SceneRunResult {
  nlohmann::json record;
  PolygonMesh mesh;
};

/// One run of a fracture scene, `observe` seeing every converged point. Throws InputError for a
/// scene, variant or run that does not exist.
SceneRunResult fracture_scene_run(const SceneRunChoice& choice,
                                  const FracturePathObserver& observe);

/// One run of a fragmentation scene (`force`: allow a step at or above the critical one), `at_end`
/// seeing the simulation after the run. Throws InputError for a scene that is not one.
SceneRunResult fragmentation_scene_run(
    const SceneRunChoice& choice, bool force,
    const std::function<void(const ExplicitSimulation&)>& at_end);

}  // namespace vorodg
