#include "verification/harness/StudyKind.hpp"

#include <nlohmann/json.hpp>
#include <sstream>

#include "core/schema/SceneObject.hpp"
#include "core/util/Errors.hpp"
#include "verification/harness/SceneVariants.hpp"
#include "verification/report/ConvergenceTable.hpp"

namespace vorodg {

const StudyKind& study_kind(const std::string& name, const std::string& where) {
  std::string names;
  const std::vector<StudyKind>& kinds = study_kinds();
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    if (kinds[i].name == name) return kinds[i];
    names += (i == 0 ? "" : i + 1 == kinds.size() ? " or " : ", ") + kinds[i].name;
  }
  throw InputError(where + "'" + name + "': expected " + names);
}

Choices study_choices() {
  Choices choices;
  for (const StudyKind& kind : study_kinds()) choices.push_back({kind.name, kind.doc});
  return choices;
}

std::string scene_study(const std::string& text, const std::string& source) {
  const nlohmann::json root = parse_scene_json(text, source);
  SceneObject top(root, "", source);
  return top.has("study") ? top.text("study", "") : "convergence";
}

const StudyKind& scene_kind(const std::string& text, const std::string& source) {
  return study_kind(scene_study(text, source), "scene " + source + ": key 'study': ");
}

std::string key_table_markdown(const StudyKind& kind) {
  ConvergenceTable t;
  for (const SceneKey& k : kind.keys()) {
    t.start_row();
    for (const auto& [column, text] :
         {std::pair<const char*, std::string>{"key", "`" + k.name + "`"},
          {"type", k.type},
          {"default", k.fallback},
          {"range", k.range},
          {"meaning", k.doc}})
      t.add_text(column, text);
  }
  std::ostringstream md;
  t.write_markdown(md);
  return md.str();
}

std::string read_study_scene(const std::string& text, const std::string& source) {
  return scene_kind(text, source).read(text, source);
}

}  // namespace vorodg
