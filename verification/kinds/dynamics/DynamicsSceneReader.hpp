#pragma once
// The reader behind parse_dynamics_scene (internal to verification/kinds/dynamics): the scene's
// keys with defaults and ranges from the key table (DynamicsKeys) through the harness's
// SceneKeyReader, every value used noted for the echo. The problems' keys are read in
// DynamicsScene.cpp, the fragmentation keys in FragmentationKeys.cpp, the impact problems' in
// ImpactKeys.cpp.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "verification/harness/SceneKeyReader.hpp"
#include "verification/kinds/dynamics/DynamicsKeys.hpp"
#include "verification/kinds/dynamics/DynamicsScene.hpp"

namespace vorodg {

/// A scene with `perturb` as variants perturb-<i> (PerturbedScene.cpp).
DynamicsScene perturbed_scene(const nlohmann::json& root, const std::string& source, bool force);

/// Reads one scene's keys: defaults and ranges from the key table, every value used noted.
class DynamicsSceneReader : public SceneKeyReader {
 public:
  DynamicsSceneReader(const nlohmann::json& root, const std::string& source, bool force)
      : SceneKeyReader(dynamics_scene_keys(), root, source), force_(force) {}

  DynamicsScene read();

 private:
  void read_bodies();
  void read_material();
  /// `element` and `vem_stabilization`: the element family of every run.
  void read_element();
  void read_wave_bar();
  void read_wall();
  void read_contact();
  void read_time();
  /// fragmentation: the cohesive law, the criterion and the strip's strain rate
  /// (FragmentationKeys.cpp).
  void read_fracture();
  /// gravity, and the column's and the projectile's keys (ImpactKeys.cpp).
  void read_impact();
  /// The plane a column-impact column falls on: through its bottom-left corner, tilted by the
  /// obliquity (ImpactKeys.cpp).
  DynamicsWall column_wall() const;
  /// Rough length of a run when time.end is not given (docs: the key table).
  void default_end();
  /// A key the problem does not use, given anyway: refused, naming the problem.
  void refuse_unless(bool applies, const std::string& key) {
    if (!applies && top_.has(key))
      top_.fail_value(key, "not used by problem " + dynamics_problem_name(s_.problem));
  }

  bool force_;
  DynamicsScene s_;
};

}  // namespace vorodg
