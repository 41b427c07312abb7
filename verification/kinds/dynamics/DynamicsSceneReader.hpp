#pragma once
// The reader behind parse_dynamics_scene (internal to verification/kinds/dynamics): the scene's
// keys with defaults and ranges from the key table (DynamicsKeys) through core's
// SceneKeyReader, every value used noted for the echo. Each problem reads its own keys through it
// (dynamics/problems/, through the SceneKeyReader it is); the fragmentation keys are read in
// FragmentationKeys.cpp.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/schema/SceneKeyReader.hpp"
#include "verification/kinds/dynamics/DynamicsKeys.hpp"
#include "verification/kinds/dynamics/DynamicsScene.hpp"

namespace vorodg {

/// A scene with `perturb` as variants perturb-<i> (PerturbedScene.cpp).
DynamicsScene perturbed_scene(const nlohmann::json& root, const std::string& source, bool force);
/// `time.refinement` (TimeRefinement.cpp): each part of `top` (itself, or each variant) that has
/// one becomes one part per fraction, its safety times the fraction, labelled dt-<fraction>
/// (<label>/dt-<fraction> for a variant). Throws InputError beside `perturb`.
DynamicsScene refined_scene(DynamicsScene top, const std::string& source);

/// Reads one scene's keys: defaults and ranges from the key table, every value used noted.
class DynamicsSceneReader : public SceneKeyReader {
 public:
  DynamicsSceneReader(const nlohmann::json& root, const std::string& source, bool force)
      : SceneKeyReader(dynamics_scene_keys(), root, source), force_(force) {}

  DynamicsScene read();

 private:
  /// `problem`, and the keys of other problems refused.
  void read_problem();
  /// The first body, with the problem's defaults, and gravity.
  void read_body();
  void read_material();
  /// `element` and `vem_stabilization`: the element family of every run.
  void read_element();
  void read_wall();
  void read_contact();
  void read_time();
  /// `time.refinement`, checked: two or more descending fractions in (0, 1].
  void read_refinement(SceneObject& t);
  /// fragmentation: the cohesive law and the criterion (FragmentationKeys.cpp).
  void read_fracture();

  bool force_;
  DynamicsScene s_;
  std::shared_ptr<DynamicsProblem> problem_;  // being read; the scene holds it when done
};

}  // namespace vorodg
