// The extremes study's scene: every entry of "sweeps" is merged (JSON merge patch) over the
// top-level keys and read as a scene of its own, so each sweep is validated like any scene.
#include <algorithm>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>

#include "core/util/Errors.hpp"
#include "verification/harness/SceneObject.hpp"
#include "verification/study/Scene.hpp"

namespace vorodg {

using nlohmann::json;

/// An extremes scene: every entry of "sweeps" is merged (JSON merge patch) over the top-level
/// keys and read as a scene of its own, so each sweep is validated like any scene.
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
    static const std::vector<std::string> sweep_keys = {
        "name", "axis", "baseline", "expected_rate", "degraded_factor", "broken_factor"};
    static const std::set<std::string> scene_keys = {"problems",        "domain",       "material",
                                                     "meshes",          "formulations", "outputs",
                                                     "patch_tolerance", "reference"};
    for (const auto& [key, ignored] : sweeps[i].items()) {
      if (scene_keys.count(key) ||
          std::find(sweep_keys.begin(), sweep_keys.end(), key) != sweep_keys.end())
        continue;
      for (const std::string& known : sweep_keys)  // a misspelt sweep key: suggest it here
        if (edit_distance(key, known) < 4)
          throw InputError("scene " + source + ": unknown key '" + where + "." + key +
                           "' (did you mean '" + known + "'?)");
    }
    for (const std::string& key : sweep_keys) patch.erase(key);
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
    sweep->expected_rate = s.number("expected_rate", sweep->expected_rate);
    sweep->degraded_factor = s.number("degraded_factor", sweep->degraded_factor);
    sweep->broken_factor = s.number("broken_factor", sweep->broken_factor);
    if (!(sweep->degraded_factor > 1 && sweep->broken_factor > sweep->degraded_factor))
      s.fail_value("broken_factor", "expected 1 < degraded_factor < broken_factor");
    scene.sweeps.push_back(sweep);
  }
  return scene;
}

}  // namespace vorodg
