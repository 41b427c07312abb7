#include "verification/harness/SceneVariants.hpp"

#include "core/schema/SceneObject.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {

nlohmann::json parse_scene_json(const std::string& text, const std::string& source) {
  nlohmann::json root;
  try {
    root = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for 1e400
    throw InputError("scene " + source + ": not valid JSON (" + std::string(e.what()) + ")");
  }
  SceneObject(root, "", source);  // "the top level: expected an object", as every reader says
  return root;
}

std::vector<SceneVariant> scene_variants(const nlohmann::json& root, const std::string& source,
                                         nlohmann::json& base) {
  base = root;
  base.erase("variants");
  const nlohmann::json& list = root.at("variants");
  if (!list.is_array() || list.empty())
    throw InputError("scene " + source + ": variants: expected a non-empty array of objects");
  std::vector<SceneVariant> variants;
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (!list[i].is_object() || !list[i].contains("label"))
      throw InputError("scene " + source + ": variants[" + std::to_string(i) +
                       "]: expected an object with a label");
    nlohmann::json merged = base;
    merged.merge_patch(list[i]);
    variants.push_back({merged, source + " variants[" + std::to_string(i) + "]"});
  }
  return variants;
}

}  // namespace vorodg
