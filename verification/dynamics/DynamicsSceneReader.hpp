#pragma once
// The reader behind parse_dynamics_scene (internal to verification/dynamics): the scene's keys
// with defaults and ranges from the key table (DynamicsKeys), every value used noted for the
// echo. The primitives are in DynamicsSceneReader.cpp, the problems' keys in DynamicsScene.cpp,
// the fragmentation keys in FragmentationKeys.cpp, the impact problems' in ImpactKeys.cpp.
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "verification/dynamics/DynamicsScene.hpp"
#include "verification/study/SceneObject.hpp"

namespace vorodg {

std::string vector_text(std::initializer_list<double> v);
std::string point_text(const Point& p);
std::string rect_text(const Rectangle& r);

/// A scene with `perturb` as variants perturb-<i> (PerturbedScene.cpp).
DynamicsScene perturbed_scene(const nlohmann::json& root, const std::string& source, bool force);

/// Reads one scene's keys: defaults and ranges from the key table, every value used noted.
class DynamicsSceneReader {
 public:
  DynamicsSceneReader(const nlohmann::json& root, const std::string& source, bool force)
      : source_(source), force_(force), top_(root, "", source) {}

  DynamicsScene read();

 private:
  SceneObject object(const std::string& key) {
    static const nlohmann::json empty = nlohmann::json::object();
    return SceneObject(top_.has(key) ? top_.at(key) : empty, key, source_);
  }
  static std::string leaf(const std::string& full) { return full.substr(full.rfind('.') + 1); }
  void note(const std::string& key, const std::string& value) { notes_[key] = value; }

  double number(SceneObject& o, const std::string& full, std::optional<double> fallback = {});
  int integer(SceneObject& o, const std::string& full, std::optional<int> fallback = {});
  bool flag(SceneObject& o, const std::string& full);
  /// `allowed`: the accepted words, each with a space either side; `fallback` replaces the key
  /// table's default where that depends on the study.
  std::string word(SceneObject& o, const std::string& full, const std::string& allowed,
                   const std::optional<std::string>& fallback = {});
  Point point(SceneObject& o, const std::string& full, const Point& fallback);
  Rectangle rectangle(SceneObject& o, const std::string& full, const Rectangle& fallback);

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
  void refuse_unless(bool applies, const std::string& key);

  const std::string& source_;
  bool force_;
  SceneObject top_;
  DynamicsScene s_;
  std::map<std::string, std::string> notes_;
};

}  // namespace vorodg
