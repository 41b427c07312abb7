#pragma once
// A scene names one study (docs/design.md, "Studies, scenes and reports"): the problems, the
// material, the mesh families with their levels and realizations, the formulations with their
// knobs. Every key is documented in docs/scenes.md and validated through the settings schema
// (verification/solve/SettingsSchema.hpp): an unknown key or a wrong type is an error naming the
// file and the key (with the nearest valid key suggested).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/Rectangle.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "verification/harness/MeshBlock.hpp"
#include "verification/model/Choices.hpp"
#include "verification/solve/SolveRun.hpp"
#include "verification/static/TradeoffSettings.hpp"

namespace vorodg {

struct SceneFormulation {
  std::string label;  // default: the name, plus the knobs that differ from the defaults
  // Formulation name, element and DG options, mean dilation; and the scene's material (E, the
  // first nu, plane, load) and outputs, so that a run needs only its problem, nu and k_p.
  SolveSettings settings;
  std::vector<double> kp;  // DG: one run per value (empty for CG)
  bool is_dg() const { return !kp.empty(); }
};

struct Scene {
  std::filesystem::path path;
  std::string name;
  std::string description;
  std::string study = "convergence";  // one of study_choices()
  std::vector<std::string> problems;
  Rectangle domain;
  double E = 1.0;
  std::vector<double> nu;
  PlaneModel plane = PlaneModel::stress;
  double load = 1.0;
  std::vector<SceneMesh> meshes;
  std::vector<SceneFormulation> formulations;
  bool energy_error = true;
  double patch_tolerance = 1e-10;  // patch-suite: errors at most this pass
  std::string reference;           // key into data/reference/published.json (optional)
  TradeoffSettings tradeoff;       // trade-off: admission, timing and the recommendation

  // extremes: the sweeps, each a scene of its own (the top-level keys with the sweep's keys
  // merged over them), run into a subfolder named after it.
  std::vector<std::shared_ptr<const Scene>> sweeps;
  // A sweep of an extremes study: what it varies and what its verdicts compare against.
  std::string axis;               // nu | kp | aspect | perturbation | regularization | h
  std::string baseline = "none";  // first-nu | cg | first-mesh | coarsest-level | none
  double expected_rate = 2.0;     // coarsest-level: the error expected to fall as h^rate
  double degraded_factor = 3.0;   // error above this times the baseline: degraded
  double broken_factor = 30.0;    // error above this times the baseline: broken
};

/// The top-level blocks a static kind's scenes take besides the common keys: each kind passes
/// its own (the extremes kind: sweeps; the trade-off kind: tradeoff), so the reader names no kind.
struct StaticSceneForm {
  bool sweeps = false;    // `sweeps`: the scene is a list of sweeps, each a study of its own
  bool tradeoff = false;  // `tradeoff`: the trade-off settings block
};

/// Reads and validates a scene. Throws InputError naming the file and the key.
Scene read_scene(const std::filesystem::path& path, const StaticSceneForm& form = {});
/// The same from text (`source` names it in messages).
Scene parse_scene(const std::string& text, const std::string& source,
                  const StaticSceneForm& form = {});

}  // namespace vorodg
