#pragma once
// `variants` in a scene: a list of objects, each with a `label`, merged over the scene's other
// top-level keys (JSON merge patch). Each variant is a study of its own, run into the subfolder
// named by its label. Every kind that takes variants reads them here.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace vorodg {

struct SceneVariant {
  nlohmann::json root;  // the top-level keys with the variant's merged over them
  std::string source;   // "<file> variants[i]", for messages
};

/// The scene's text as a JSON object; throws InputError if it is not valid JSON or not an
/// object (every kind's reader starts here).
nlohmann::json parse_scene_json(const std::string& text, const std::string& source);

/// The scene without `variants` (`base`) and each variant merged over it. Throws InputError
/// unless `variants` is a non-empty list of objects with a label.
std::vector<SceneVariant> scene_variants(const nlohmann::json& root, const std::string& source,
                                         nlohmann::json& base);

/// The parts a study runs: the scene itself, or each of its variants.
template <class SceneT>
std::vector<const SceneT*> study_parts(const SceneT& scene) {
  std::vector<const SceneT*> parts;
  if (scene.variants.empty()) parts.push_back(&scene);
  for (const SceneT& v : scene.variants) parts.push_back(&v);
  return parts;
}

/// Where a part writes: the study's folder, or a variant's subfolder.
inline std::filesystem::path part_folder(const std::filesystem::path& out,
                                         const std::string& label) {
  return label.empty() ? out : out / label;
}

}  // namespace vorodg
