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
#include "verification/model/Choices.hpp"
#include "verification/solve/SolveRun.hpp"
#include "verification/study/TradeoffSettings.hpp"

namespace vorodg {

struct SceneMesh {
  std::string label;  // default: the family name
  MeshFamily family = MeshFamily::rcp;
  std::vector<double> sizes;  // d (rcp, tri) or h (hex, perturbed-hex, quad), coarse to fine
  /// file: one .vtu per level, coarse to fine, resolved against the scene's folder. Their sizes
  /// are the meshes' h_avg, so that every study counts levels by `sizes`.
  std::vector<std::filesystem::path> files;
  int realizations = 1;
  std::uint64_t seed = MeshSpec{}.seed;
  double perturbation = MeshSpec{}.perturbation;
  double regularization = MeshSpec{}.regularization;
  bool symmetric = false;   // rcp: mirrored about the vertical mid-line
  bool notch_only = false;  // symmetric "notch": mirrored along the notch and at the top only

  /// What the generator needs for one realization of one level.
  MeshSpec spec(const Rectangle& domain, int level, std::uint64_t realization_seed) const;
};

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

class SceneObject;
/// One entry of "meshes" (the keys of docs/scenes.md); every study kind reads its meshes so.
SceneMesh read_mesh(SceneObject& m, const Rectangle& domain);

/// Reads and validates a scene. Throws InputError naming the file and the key.
Scene read_scene(const std::filesystem::path& path);
/// The same from text (`source` names it in messages).
Scene parse_scene(const std::string& text, const std::string& source);

}  // namespace vorodg
