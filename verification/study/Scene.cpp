#include "verification/study/Scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string_view>

#include "core/io/AtomicFile.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"

namespace vorodg {
namespace {

using nlohmann::json;

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = up;
    }
  }
  return row[b.size()];
}

/// Reads one JSON object of a scene, knowing its place ("meshes[1]") for messages, and refusing
/// keys it was not asked about.
class SceneObject {
 public:
  SceneObject(const json& value, std::string where, const std::string& source)
      : value_(value), where_(std::move(where)), source_(source) {
    if (!value.is_object()) fail("", "an object", value);
  }

  [[noreturn]] void fail(const std::string& key, const std::string& expected, const json& found) const {
    const std::string where = path(key).empty() ? "the top level" : "key '" + path(key) + "'";
    throw InputError("scene " + source_ + ": " + where + ": expected " + expected + ", found " +
                     describe(found));
  }
  [[noreturn]] void fail_value(const std::string& key, const std::string& what) const {
    throw InputError("scene " + source_ + ": key '" + path(key) + "': " + what);
  }

  bool has(const std::string& key) { return known(key), value_.contains(key); }
  const json& at(const std::string& key) {
    known(key);
    if (!value_.contains(key)) {
      for (const auto& [present, ignored] : value_.items())
        if (edit_distance(present, key) < 4)
          throw InputError("scene " + source_ + ": unknown key '" + path(present) +
                           "' (did you mean '" + key + "'?)");
      fail_value(key, "missing (required)");
    }
    return value_.at(key);
  }
  std::string text(const std::string& key, const std::string& fallback) {
    if (!has(key)) return fallback;
    const json& v = value_.at(key);
    if (!v.is_string()) fail(key, "a string", v);
    return v.get<std::string>();
  }
  double number(const std::string& key, double fallback) {
    if (!has(key)) return fallback;
    const json& v = value_.at(key);
    if (!v.is_number()) fail(key, "a number", v);
    return v.get<double>();
  }
  int integer(const std::string& key, int fallback) {
    if (!has(key)) return fallback;
    const json& v = value_.at(key);
    if (!v.is_number_integer()) fail(key, "an integer", v);
    // get<int>() would wrap silently (4294967299 -> 3): refuse what an int cannot hold.
    constexpr int lo = std::numeric_limits<int>::min(), hi = std::numeric_limits<int>::max();
    if (v.is_number_unsigned() ? v.get<std::uint64_t>() > static_cast<std::uint64_t>(hi)
                               : v.get<std::int64_t>() < lo || v.get<std::int64_t>() > hi)
      fail(key, "an integer in " + std::to_string(lo) + ".." + std::to_string(hi), v);
    return v.get<int>();
  }
  bool flag(const std::string& key, bool fallback) {
    if (!has(key)) return fallback;
    const json& v = value_.at(key);
    if (!v.is_boolean()) fail(key, "true or false", v);
    return v.get<bool>();
  }
  /// A number or a list of numbers (at least one).
  std::vector<double> numbers(const std::string& key, std::vector<double> fallback) {
    if (!has(key)) return fallback;
    const json& v = value_.at(key);
    if (v.is_number()) return {v.get<double>()};
    if (!v.is_array() || v.empty()) fail(key, "a number or a non-empty array of numbers", v);
    std::vector<double> out;
    for (const json& x : v) {
      if (!x.is_number()) fail(key, "an array of numbers", v);
      out.push_back(x.get<double>());
    }
    return out;
  }
  std::vector<std::string> texts(const std::string& key, std::vector<std::string> fallback) {
    if (!has(key)) return fallback;
    const json& v = value_.at(key);
    if (v.is_string()) return {v.get<std::string>()};
    if (!v.is_array() || v.empty()) fail(key, "a string or a non-empty array of strings", v);
    std::vector<std::string> out;
    for (const json& x : v) {
      if (!x.is_string()) fail(key, "an array of strings", v);
      out.push_back(x.get<std::string>());
    }
    return out;
  }
  /// After reading: any key not asked about is an error, with the nearest known key suggested.
  void finish() const {
    for (const auto& [key, ignored] : value_.items()) {
      if (asked_.count(key)) continue;
      std::string nearest;
      std::size_t best = 4;
      for (const std::string& k : asked_)
        if (const std::size_t d = edit_distance(key, k); d < best) best = d, nearest = k;
      throw InputError("scene " + source_ + ": unknown key '" + path(key) + "'" +
                       (nearest.empty() ? "" : " (did you mean '" + nearest + "'?)"));
    }
  }
  std::string path(const std::string& key) const {
    return where_.empty() ? key : key.empty() ? where_ : where_ + "." + key;
  }

 private:
  void known(const std::string& key) { asked_.insert(key); }
  static std::string describe(const json& v) {
    std::string text = v.dump();
    if (text.size() > 40) text = text.substr(0, 37) + "...";
    return std::string(v.type_name()) + " " + text;
  }

  const json& value_;
  std::string where_;
  const std::string& source_;
  std::set<std::string> asked_;
};

SceneMesh read_mesh(SceneObject& m, const Rectangle& domain) {
  SceneMesh mesh;
  const std::string family = m.text("family", "rcp");
  try {
    mesh.family = parse_family(family);
  } catch (const InputError& e) {
    m.fail_value("family", e.what());
  }
  if (mesh.family == MeshFamily::file) m.fail_value("family", "'file' is not a generated family");
  mesh.label = m.text("label", family);
  mesh.sizes = m.numbers("sizes", {});
  if (mesh.sizes.empty()) m.fail_value("sizes", "missing (required): the d or h of every level");
  for (std::size_t i = 0; i < mesh.sizes.size(); ++i) {
    if (!(mesh.sizes[i] > 0)) m.fail_value("sizes", "every size must be > 0");
    if (mesh.sizes[i] > domain.scale())
      m.fail_value("sizes", "size " + fmt(mesh.sizes[i]) + " exceeds the domain's longer side " +
                                fmt(domain.scale()));
    if (domain.area() / (mesh.sizes[i] * mesh.sizes[i]) > 1.5e8)
      m.fail_value("sizes", "size " + fmt(mesh.sizes[i]) + " gives more than 1.5e8 cells");
    if (i > 0 && !(mesh.sizes[i] < mesh.sizes[i - 1]))
      m.fail_value("sizes", "levels must go from coarse to fine (strictly decreasing), found " +
                                fmt(mesh.sizes[i - 1]) + " then " + fmt(mesh.sizes[i]));
  }
  mesh.realizations = m.integer("realizations", 1);
  if (mesh.realizations < 1) m.fail_value("realizations", "expected at least 1");
  const double seed = m.number("seed", 1);
  if (seed < 0 || seed != std::floor(seed) || seed > 9007199254740992.0)
    m.fail_value("seed", "expected an integer in 0..2^53, found " + fmt(seed));
  mesh.seed = static_cast<std::uint64_t>(seed);
  mesh.perturbation = m.number("perturbation", 0.3);
  if (!(mesh.perturbation >= 0 && mesh.perturbation < 0.5))
    m.fail_value("perturbation", "expected 0 <= r < 0.5, found " + fmt(mesh.perturbation));
  mesh.regularization = m.number("regularization", 0.1);
  if (!(mesh.regularization >= 0 && mesh.regularization < 1))
    m.fail_value("regularization", "expected a fraction of d in [0, 1), found " + fmt(mesh.regularization));
  m.finish();
  return mesh;
}

SceneFormulation read_formulation(SceneObject& f) {
  SceneFormulation out;
  SolveSettings& s = out.settings;
  s.formulation = f.text("name", "cg");
  if (s.formulation != "cg") {
    try {
      parse_dg_method(s.formulation);
    } catch (const InputError& e) {
      f.fail_value("name", e.what());
    }
  }
  s.element.divergence_correction = f.flag("correction", true);
  s.element.rule_points = f.integer("rule", 3);
  s.element.weights.refinement = f.integer("refinement", s.element.weights.refinement);
  s.element.weights.degree = f.integer("degree", s.element.weights.degree);
  s.mean_dilation = f.flag("mean_dilation", false);
  s.dg.tolerance = f.number("tolerance", s.dg.tolerance);
  s.dg.max_iterations = f.integer("max_iterations", s.dg.max_iterations);
  s.dg.local_h = f.flag("local_h", false);
  s.dg.al_update_kp = f.flag("al_update_kp", false);
  s.dg.sipg_mean_stress = f.flag("sipg_mean_stress", false);
  s.dg.sipg_sign = f.integer("sipg_sign", -1);
  if (!(s.dg.tolerance > 0)) f.fail_value("tolerance", "expected > 0, found " + fmt(s.dg.tolerance));
  if (s.dg.max_iterations < 1)
    f.fail_value("max_iterations", "expected >= 1, found " + std::to_string(s.dg.max_iterations));
  if (s.dg.sipg_sign != -1 && s.dg.sipg_sign != 1)
    f.fail_value("sipg_sign", "expected -1 or 1, found " + std::to_string(s.dg.sipg_sign));
  if (s.formulation != "cg") {
    out.kp = f.numbers("kp", {1e3});
    for (double k : out.kp)
      if (!(k > 0)) f.fail_value("kp", "every k_p must be > 0 (relative to E)");
  } else if (f.has("kp")) {
    f.fail_value("kp", "only DG formulations take a penalty");
  }
  std::string label = s.formulation;
  if (!s.element.divergence_correction) label += " no-correction";
  if (s.mean_dilation) label += " mean-dilation";
  if (s.element.rule_points != 3) label += " rule-" + std::to_string(s.element.rule_points);
  out.label = f.text("label", label);
  if (s.element.rule_points != 1 && s.element.rule_points != 3 && s.element.rule_points != 6)
    f.fail_value("rule", "expected 1, 3 or 6, found " + std::to_string(s.element.rule_points));
  try {
    check_weight_options(s.element.weights);
  } catch (const InputError& e) {
    const bool degree = std::string_view(e.what()).find("degree") != std::string_view::npos;
    f.fail_value(degree ? "degree" : "refinement", e.what());
  }
  f.finish();
  return out;
}

}  // namespace

Scene parse_extremes(const json& root, SceneObject& top, const std::string& source);

Scene parse_scene(const std::string& text, const std::string& source) {
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
  scene.study = top.text("study", "convergence");
  if (scene.study != "convergence" && scene.study != "penalty-sweep" &&
      scene.study != "patch-suite" && scene.study != "trade-off" && scene.study != "extremes")
    top.fail_value("study", "'" + scene.study +
                                "': expected convergence, penalty-sweep, patch-suite, trade-off or extremes");
  if (scene.study == "extremes") {
    Scene extremes = parse_extremes(root, top, source);
    extremes.name = scene.name;
    extremes.description = scene.description;
    extremes.study = scene.study;
    return extremes;
  }
  scene.problems = top.texts("problems", {"beam"});
  const bool beam = std::find(scene.problems.begin(), scene.problems.end(), "beam") != scene.problems.end();
  const std::vector<double> domain = top.numbers("domain", beam ? std::vector<double>{0, -0.5, 4, 0.5}
                                                                : std::vector<double>{0, 0, 2, 1});
  if (domain.size() != 4) top.fail_value("domain", "expected four numbers [x0, y0, x1, y1]");
  try {
    scene.domain = Rectangle(domain[0], domain[1], domain[2], domain[3]);
  } catch (const InputError& e) {
    top.fail_value("domain", e.what());
  }
  {
    const json material_value = top.has("material") ? top.at("material") : json::object();
    SceneObject material(material_value, "material", source);
    scene.E = material.number("E", 1.0);
    scene.nu = material.numbers("nu", {0.3});
    const std::string plane = material.text("plane", "stress");
    if (plane != "stress" && plane != "strain") material.fail_value("plane", "expected stress or strain");
    scene.plane = plane == "strain" ? PlaneModel::strain : PlaneModel::stress;
    scene.load = material.number("load", 1.0);
    material.finish();
    if (!(std::isfinite(scene.E) && scene.E > 0))
      material.fail_value("E", "expected a finite E > 0, found " + fmt(scene.E));
    for (double nu : scene.nu) {
      try {
        IsotropicElasticity(scene.E, nu, scene.plane);
      } catch (const InputError& e) {
        material.fail_value("nu", e.what());
      }
    }
  }
  // Every problem must exist, live on the domain and be solvable: refused here, not run by run.
  for (const std::string& problem : scene.problems) {
    SolveSettings settings;
    settings.problem = problem;
    settings.E = scene.E;
    settings.nu = scene.nu.front();
    settings.plane = scene.plane;
    if (problem != "beam" && problem != "patch" && problem != "patch-mixed" &&
        problem != "patch-traction" && problem != "mms")
      top.fail_value("problems", "'" + problem + "': expected beam, patch, patch-mixed, patch-traction or mms");
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
  const json& meshes = top.at("meshes");
  if (!meshes.is_array() || meshes.empty()) top.fail("meshes", "a non-empty array of mesh objects", meshes);
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    SceneObject m(meshes[i], "meshes[" + std::to_string(i) + "]", source);
    scene.meshes.push_back(read_mesh(m, scene.domain));
  }
  const json& forms = top.at("formulations");
  if (!forms.is_array() || forms.empty())
    top.fail("formulations", "a non-empty array of formulation objects", forms);
  for (std::size_t i = 0; i < forms.size(); ++i) {
    SceneObject f(forms[i], "formulations[" + std::to_string(i) + "]", source);
    scene.formulations.push_back(read_formulation(f));
  }
  {
    const json outputs_value = top.has("outputs") ? top.at("outputs") : json::object();
    SceneObject outputs(outputs_value, "outputs", source);
    scene.energy_error = outputs.flag("energy_error", true);
    outputs.finish();
  }
  scene.patch_tolerance = top.number("patch_tolerance", 1e-10);
  scene.reference = top.text("reference", "");
  top.finish();
  return scene;
}

/// An extremes scene: every entry of "sweeps" is merged (JSON merge patch) over the top-level
/// keys and read as a scene of its own, so each sweep is validated like any scene.
Scene parse_extremes(const json& root, SceneObject& top, const std::string& source) {
  const json& sweeps = top.at("sweeps");
  if (!sweeps.is_array() || sweeps.empty()) top.fail("sweeps", "a non-empty array of sweep objects", sweeps);
  json base = root;
  for (const char* key : {"name", "description", "study", "sweeps"}) base.erase(key);
  Scene scene;
  std::set<std::string> names;
  for (std::size_t i = 0; i < sweeps.size(); ++i) {
    const std::string where = "sweeps[" + std::to_string(i) + "]";
    SceneObject s(sweeps[i], where, source);
    json merged = base;
    json patch = sweeps[i];
    static const std::vector<std::string> sweep_keys = {"name", "axis", "baseline", "expected_rate",
                                                        "degraded_factor", "broken_factor"};
    static const std::set<std::string> scene_keys = {"problems", "domain", "material", "meshes",
                                                     "formulations", "outputs", "patch_tolerance", "reference"};
    for (const auto& [key, ignored] : sweeps[i].items()) {
      if (scene_keys.count(key) || std::find(sweep_keys.begin(), sweep_keys.end(), key) != sweep_keys.end())
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
    if (!names.insert(sweep->name).second) s.fail_value("name", "'" + sweep->name + "' names two sweeps");
    sweep->axis = s.text("axis", "");
    static const std::set<std::string> axes = {"nu", "kp", "aspect", "perturbation", "regularization", "h"};
    if (!axes.count(sweep->axis))
      s.fail_value("axis", "'" + sweep->axis + "': expected nu, kp, aspect, perturbation, regularization or h");
    sweep->baseline = s.text("baseline", "none");
    static const std::set<std::string> baselines = {"first-nu", "cg", "first-mesh", "coarsest-level", "none"};
    if (!baselines.count(sweep->baseline))
      s.fail_value("baseline", "'" + sweep->baseline + "': expected first-nu, cg, first-mesh, coarsest-level or none");
    const bool has_cg = std::any_of(sweep->formulations.begin(), sweep->formulations.end(),
                                    [](const SceneFormulation& f) { return f.settings.formulation == "cg"; });
    if (sweep->baseline == "cg" && !has_cg)
      s.fail_value("baseline", "'cg' needs a cg formulation in the sweep");
    sweep->expected_rate = s.number("expected_rate", 2.0);
    sweep->degraded_factor = s.number("degraded_factor", 3.0);
    sweep->broken_factor = s.number("broken_factor", 30.0);
    if (!(sweep->degraded_factor > 1 && sweep->broken_factor > sweep->degraded_factor))
      s.fail_value("broken_factor", "expected 1 < degraded_factor < broken_factor");
    scene.sweeps.push_back(sweep);
  }
  return scene;
}

Scene read_scene(const std::filesystem::path& path) {
  Scene scene = parse_scene(read_file(path), path.string());
  scene.path = path;
  return scene;
}

}  // namespace vorodg
