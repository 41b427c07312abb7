// `perturb` in a fragmentation scene (docs/fragmentation.md, "Sensitivity studies"): the
// sensitivity studies' variants, one per value of one key, or one per seed of a per-cell material
// variation beside the uniform material.
#include <nlohmann/json.hpp>

#include "core/util/Errors.hpp"
#include "verification/kinds/dynamics/DynamicsSceneReader.hpp"

namespace vorodg {
namespace {

using nlohmann::json;

/// `perturb: {variation, seeds}`: the key/values form on /material/variation_seed, with a
/// reference of the uniform material first (value "uniform") and `variation` set in the others.
json material_perturbation(const json& p, const std::string& where) {
  if (p.size() != 2 || !p["variation"].is_number() || !p.contains("seeds") ||
      !p["seeds"].is_array() || p["seeds"].empty())
    throw InputError(where + ": expected {\"variation\": x, \"seeds\": [one or more seeds]}");
  json values = json::array({"uniform"});
  for (const json& seed : p["seeds"]) values.push_back(seed);
  return {{"key", "/material/variation_seed"}, {"values", values}, {"variation", p["variation"]}};
}

}  // namespace

/// `perturb: {key, values}`: one variant per value, labelled perturb-<i>, with the key (a
/// top-level name, or a JSON pointer such as /wall/point) set to the value; or
/// `perturb: {variation, seeds}` (material_perturbation).
DynamicsScene perturbed_scene(const json& root, const std::string& source, bool force) {
  const std::string where = "scene " + source + ": perturb";
  const bool material = root["perturb"].is_object() && root["perturb"].contains("variation");
  const json p = material ? material_perturbation(root["perturb"], where) : root["perturb"];
  if (root.contains("variants")) throw InputError(where + ": expected either perturb or variants");
  if (!p.is_object() || !p.contains("key") || !p["key"].is_string() || !p.contains("values") ||
      !p["values"].is_array() || p["values"].size() < 2 || p.size() != (material ? 3 : 2))
    throw InputError(where + ": expected {\"key\": name, \"values\": [two or more values]}");
  const std::string key = p["key"];
  if (key.empty() || key == "/") throw InputError(where + ".key: expected a scene key");
  json::json_pointer pointer;
  try {
    pointer = json::json_pointer(key.front() == '/' ? key : "/" + key);
  } catch (const json::exception&) {
    throw InputError(where + ".key: '" + key + "' is not a key or a JSON pointer");
  }
  json base = root;
  base.erase("perturb");
  base["variants"] = json::array();
  for (std::size_t i = 0; i < p["values"].size(); ++i) {
    json variant = base;
    variant.erase("variants");
    if (!material || i > 0) try {  // (the material form's reference is the uniform material)
        variant[pointer] = p["values"][i];  // the whole scene, so merging it changes only this
        if (material) variant["material"]["variation"] = p["variation"];
      } catch (const json::exception&) {  // a pointer through a list or a value: no such key
        throw InputError(where + ".key: '" + key + "' names no place in the scene");
      }
    variant["label"] = "perturb-" + std::to_string(i);
    base["variants"].push_back(variant);
  }
  DynamicsScene top = parse_dynamics_scene(base.dump(), source, force);
  if (!top.fragmentation)
    throw InputError(where + ": expected study fragmentation (it compares crack states)");
  top.perturb_key = key;
  for (const json& v : p["values"]) top.perturb_values.push_back(v.dump());
  return top;
}

}  // namespace vorodg
