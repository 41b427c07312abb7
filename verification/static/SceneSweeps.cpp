// The extremes study's scene: every entry of "sweeps" is merged (JSON merge patch) over the
// top-level keys and read as a scene of its own, so each sweep is validated like any scene.
#include <algorithm>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>

#include "core/schema/SceneKeyReader.hpp"
#include "core/schema/SceneObject.hpp"
#include "core/util/Errors.hpp"
#include "verification/static/Scene.hpp"
#include "verification/static/StaticSceneKeys.hpp"

namespace vorodg {

using nlohmann::json;

/// An extremes scene: every entry of "sweeps" is merged (JSON merge patch) over the top-level
/// keys and read as a scene of its own, so each sweep is validated like any scene.
namespace {

/// The keys of a sweep block (sweeps[].name, ...) and the scene keys it may merge over the top
/// level, from the key tables.
struct SweepKeys {
  std::vector<std::string> own;
  std::set<std::string> scene;
};

const SweepKeys& sweep_keys() {
  static const SweepKeys keys = [] {
    SweepKeys k;
    const std::string prefix = "sweeps[].";
    for (const SceneKey& key : extremes_scene_table().keys)
      if (key.name.starts_with(prefix)) k.own.push_back(key.name.substr(prefix.size()));
    for (const SceneKey& key : static_scene_table().keys) {
      const std::string top = key.name.substr(0, key.name.find_first_of(".["));
      if (top != "name" && top != "description" && top != "study" && top != "tradeoff")
        k.scene.insert(top);
    }
    return k;
  }();
  return keys;
}

}  // namespace

Scene parse_extremes(const json& root, SceneObject& top, const std::string& source) {
  const json& sweeps = top.at("sweeps");
  if (!sweeps.is_array() || sweeps.empty())
    top.fail("sweeps", "a non-empty array of sweep objects", sweeps);
  json base = root;
  for (const char* key : {"name", "description", "study", "sweeps"}) base.erase(key);
  Scene scene;
  std::set<std::string> names;
  for (std::size_t i = 0; i < sweeps.size(); ++i) {
    const std::string where = "sweeps[" + std::to_string(i) + "]";
    SceneObject s(sweeps[i], where, source);
    json merged = base;
    json patch = sweeps[i];
    const std::vector<std::string>& sweep_own = sweep_keys().own;
    for (const auto& [key, ignored] : sweeps[i].items()) {
      if (sweep_keys().scene.count(key) ||
          std::find(sweep_own.begin(), sweep_own.end(), key) != sweep_own.end())
        continue;
      for (const std::string& known : sweep_own)  // a misspelt sweep key: suggest it here
        if (edit_distance(key, known) < 4)
          throw InputError("scene " + source + ": unknown key '" + where + "." + key +
                           "' (did you mean '" + known + "'?)");
    }
    for (const std::string& key : sweep_own) patch.erase(key);
    merged.merge_patch(patch);
    merged["study"] = "convergence";
    auto sweep = std::make_shared<Scene>(parse_scene(merged.dump(), source + " " + where));
    sweep->name = s.text("name", "");
    if (sweep->name.empty() || sweep->name.find_first_of("/\\ ") != std::string::npos)
      s.fail_value("name", "expected a non-empty folder name without '/', '\\' or spaces");
    if (!names.insert(sweep->name).second)
      s.fail_value("name", "'" + sweep->name + "' names two sweeps");
    sweep->axis = s.text("axis", "");
    if (!is_choice(sweep_axis_choices(), sweep->axis))
      s.fail_value("axis", "'" + sweep->axis + "': expected " + choice_list(sweep_axis_choices()));
    sweep->baseline = s.text("baseline", sweep->baseline);
    if (!is_choice(baseline_choices(), sweep->baseline))
      s.fail_value("baseline",
                   "'" + sweep->baseline + "': expected " + choice_list(baseline_choices()));
    const bool has_cg =
        std::any_of(sweep->formulations.begin(), sweep->formulations.end(),
                    [](const SceneFormulation& f) { return f.settings.formulation == "cg"; });
    if (sweep->baseline == "cg" && !has_cg)
      s.fail_value("baseline", "'cg' needs a cg formulation in the sweep");
    const auto number = [&](const std::string& name, double fallback) {
      return checked_number(s, name, static_key("sweeps[]." + name), fallback);
    };
    sweep->expected_rate = number("expected_rate", sweep->expected_rate);
    sweep->degraded_factor = number("degraded_factor", sweep->degraded_factor);
    sweep->broken_factor = number("broken_factor", sweep->broken_factor);
    if (!(sweep->degraded_factor > 1 && sweep->broken_factor > sweep->degraded_factor))
      s.fail_value("broken_factor", "expected 1 < degraded_factor < broken_factor");
    scene.sweeps.push_back(sweep);
  }
  return scene;
}

}  // namespace vorodg
