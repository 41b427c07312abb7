#include "verification/static/Scene.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>

#include "core/io/AtomicFile.hpp"
#include "core/io/VtuMesh.hpp"
#include "core/mesh/MeshValidator.hpp"
#include "core/schema/SceneKeyReader.hpp"
#include "core/schema/SceneObject.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "verification/harness/CommonKeys.hpp"
#include "verification/harness/StudyKind.hpp"
#include "verification/solve/SettingsSchema.hpp"
#include "verification/static/StaticSceneKeys.hpp"

namespace vorodg {
namespace {

using nlohmann::json;

/// Reads the value of one schema setting from a scene object into `s` (absent: unchanged).
void read_setting(SceneObject& object, const SettingSpec& spec, SolveSettings& s) {
  switch (spec.kind) {
    case SettingKind::choice: {
      const std::string text = object.text(spec.name, spec.get_text(s));
      if (const auto message = check_text(spec, text)) object.fail_value(spec.name, *message);
      spec.set_text(s, text);
      break;
    }
    case SettingKind::flag: spec.set(s, object.flag(spec.name, spec.get(s) != 0.0)); break;
    case SettingKind::integer:
      spec.set(s, object.integer(spec.name, static_cast<int>(spec.get(s))));
      break;
    case SettingKind::number: spec.set(s, object.number(spec.name, spec.get(s))); break;
  }
}

/// Every schema setting of `scope` read from `object`, then validated; the k_p of a
/// formulation is a list (one run per value) and read apart.
void read_scope(SceneObject& object, SettingScope scope, SolveSettings& s) {
  for (const SettingSpec& spec : setting_specs())
    if (spec.scope == scope && spec.name != "kp") read_setting(object, spec, s);
  if (const auto error = check_settings(s); error && error->spec->scope == scope)
    object.fail_value(error->spec->name, error->message);
}

std::string default_label(const SolveSettings& s) {
  std::string label = s.formulation;
  if (s.element.family != SolveSettings{}.element.family)
    label.append(" ").append(element_name(s.element.family));
  if (!s.element.divergence_correction) label += " no-correction";
  if (s.mean_dilation) label += " mean-dilation";
  if (s.element.rule_points != SolveSettings{}.element.rule_points)
    label += " rule-" + std::to_string(s.element.rule_points);
  if (s.formulation == "cg") return label;
  DgOptions plain;  // the formulation's defaults
  plain.formulation = dg_options(s).formulation;
  // Appended piece by piece: g++ 12 warns falsely (-Wrestrict) on " " + std::string here.
  if (penalty_scaling(dg_options(s)) != penalty_scaling(plain))
    label.append(" ").append(penalty_name(penalty_scaling(dg_options(s))));
  if (interface_traction(dg_options(s)) != interface_traction(plain))
    label.append(" ").append(traction_name(interface_traction(dg_options(s)))).append("-stress");
  if (s.dg.weighted_average) label += " weighted";
  return label;
}

SceneFormulation read_formulation(SceneObject& f, const SolveSettings& material) {
  SceneFormulation out;
  out.settings = material;
  SolveSettings& s = out.settings;
  read_scope(f, SettingScope::formulation, s);
  const SettingSpec& kp = setting_spec("kp");
  if (s.formulation != "cg") {
    out.kp = f.numbers(kp.name, {kp.get(s)});
    for (double k : out.kp)
      if (const auto message = check_value(kp, k)) f.fail_value(kp.name, *message);
  } else if (f.has(kp.name)) {
    f.fail_value(kp.name, "only DG formulations take a penalty");
  }
  out.label = f.text("label", default_label(s));
  f.finish();
  return out;
}

/// The material block: E, nu (a list: one run per value), the plane model and the beam's load.
SolveSettings read_material(SceneObject& top, Scene& scene) {
  const json material_value = top.has("material") ? top.at("material") : json::object();
  SceneObject material(material_value, "material", top.source());
  SolveSettings s;
  const SettingSpec& nu = setting_spec("nu");
  scene.nu = material.numbers(nu.name, {nu.get(s)});
  for (double value : scene.nu) {
    if (const auto message = check_value(nu, value)) material.fail_value(nu.name, *message);
  }
  s.nu = scene.nu.front();
  for (const SettingSpec& spec : setting_specs())
    if (spec.scope == SettingScope::material && spec.name != nu.name)
      read_setting(material, spec, s);
  if (const auto error = check_settings(s); error && error->spec->scope == SettingScope::material)
    material.fail_value(error->spec->name, error->message);
  material.finish();
  scene.E = s.E;
  scene.plane = s.plane;
  scene.load = s.load;
  return s;
}

/// Every problem must exist, live on the domain and be solvable: refused here, not run by run.
void check_problems(SceneObject& top, const Scene& scene, const SolveSettings& material) {
  const SettingSpec& problem_spec = setting_spec("problem");
  for (const std::string& problem : scene.problems) {
    if (const auto message = check_text(problem_spec, problem))
      top.fail_value("problems", *message);
    SolveSettings settings = material;
    settings.problem = problem;
    std::unique_ptr<ExactSolution> exact;
    try {
      exact = make_problem(settings, scene.domain);
    } catch (const InputError& e) {
      top.fail_value("domain", e.what());
    }
    if (!exact->has_dirichlet_side())
      top.fail_value("problems", "'" + problem +
                                     "' prescribes no displacement on any side: every run would be "
                                     "singular, expected a problem with a Dirichlet side");
  }
}

void read_domain(SceneObject& top, Scene& scene) {
  const bool beam =
      std::find(scene.problems.begin(), scene.problems.end(), "beam") != scene.problems.end();
  const std::vector<double> domain = top.numbers(
      "domain", beam ? std::vector<double>{0, -0.5, 4, 0.5} : std::vector<double>{0, 0, 2, 1});
  if (domain.size() != 4) top.fail_value("domain", "expected four numbers [x0, y0, x1, y1]");
  try {
    scene.domain = Rectangle(domain[0], domain[1], domain[2], domain[3]);
  } catch (const InputError& e) {
    top.fail_value("domain", e.what());
  }
}

template <class Read>
void read_list(SceneObject& top, const std::string& key, const std::string& what, Read read) {
  const json& list = top.at(key);
  if (!list.is_array() || list.empty()) top.fail(key, "a non-empty array of " + what, list);
  for (std::size_t i = 0; i < list.size(); ++i) {
    SceneObject item(list[i], key + "[" + std::to_string(i) + "]", top.source());
    read(item);
  }
}

}  // namespace

Scene parse_extremes(const json& root, SceneObject& top, const std::string& source);

Scene parse_scene(const std::string& text, const std::string& source, const StaticSceneForm& form) {
  json root;
  try {
    root = json::parse(text);
  } catch (const json::exception& e) {  // parse_error, and out_of_range for 1e400
    throw InputError("scene " + source + ": not valid JSON (" + std::string(e.what()) + ")");
  }
  Scene scene;
  SceneObject top(root, "", source);
  scene.name = top.text("name", std::filesystem::path(source).stem().string());
  scene.description = top.text("description", "");
  scene.study = top.text("study", scene.study);
  if (!is_choice(study_choices(), scene.study))
    top.fail_value("study", "'" + scene.study + "': expected " + choice_list(study_choices()));
  if (form.sweeps) {
    Scene extremes = parse_extremes(root, top, source);
    extremes.name = scene.name;
    extremes.description = scene.description;
    extremes.study = scene.study;
    return extremes;
  }
  scene.problems = top.texts("problems", {SolveSettings{}.problem});
  read_domain(top, scene);
  const SolveSettings material = read_material(top, scene);
  check_problems(top, scene, material);
  read_list(top, "meshes", "mesh objects",
            [&](SceneObject& m) { scene.meshes.push_back(read_mesh(m, scene.domain)); });
  read_list(top, "formulations", "formulation objects",
            [&](SceneObject& f) { scene.formulations.push_back(read_formulation(f, material)); });
  {
    const json outputs_value = top.has("outputs") ? top.at("outputs") : json::object();
    SceneObject outputs(outputs_value, "outputs", source);
    SolveSettings s;
    read_scope(outputs, SettingScope::outputs, s);
    scene.energy_error = s.energy_error;
    for (SceneFormulation& f : scene.formulations) f.settings.energy_error = s.energy_error;
    outputs.finish();
  }
  scene.patch_tolerance =
      checked_number(top, "patch_tolerance", static_key("patch_tolerance"), scene.patch_tolerance);
  scene.reference = top.text("reference", "");
  if (top.has("tradeoff")) {
    if (!form.tradeoff)
      top.fail_value("tradeoff", "study '" + scene.study + "' does not take a tradeoff block");
    SceneObject block(top.at("tradeoff"), "tradeoff", source);
    scene.tradeoff = read_tradeoff_settings(block);
  }
  top.finish();
  return scene;
}

Scene read_scene(const std::filesystem::path& path, const StaticSceneForm& form) {
  Scene scene = parse_scene(read_file(path), path.string(), form);
  scene.path = path;
  return scene;
}

}  // namespace vorodg
