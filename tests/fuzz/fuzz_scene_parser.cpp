// libFuzzer target: a scene file of any study kind read as `vorodg run` reads it (the `study` key
// picks the kind's reader from the registry, which validates every key). Findings: crashes,
// sanitizer reports, exceptions other than our error types, hangs, and a static scene accepted
// although a value breaks what docs/scenes.md and Scene.hpp promise. Seeded with the corpus and
// every shipped scene (data/scenes).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "FuzzSupport.hpp"
#include "core/util/Errors.hpp"
#include "verification/harness/StudyKind.hpp"
#include "verification/static/Scene.hpp"

namespace {

using namespace vorodg;
using fuzz::require;

using nlohmann::json;

/// An integer key that was accepted holds the value written in the file (no silent wrap-around).
void check_integer(const json& object, const char* key, long long stored,
                   const std::string& where) {
  if (!object.contains(key)) return;
  require(object.at(key) == json(stored), where + "." + key + " written " + object.at(key).dump() +
                                              ", accepted as " + std::to_string(stored));
}

/// What every static scene (and every sweep of an extremes scene) promises.
void check_values(const Scene& s) {
  require(std::isfinite(s.domain.area()) && s.domain.area() > 0,
          "scene domain of area " + std::to_string(s.domain.area()));
  require(!s.problems.empty() && !s.nu.empty(), "scene without problems or nu");
  for (const std::string& p : s.problems)  // docs/scenes.md: the problems make_problem knows
    require(
        p == "beam" || p == "patch" || p == "patch-mixed" || p == "patch-traction" || p == "mms",
        "scene accepted with unknown problem '" + p + "'");
  require(std::isfinite(s.E) && s.E > 0, "scene E " + std::to_string(s.E));
  require(!s.meshes.empty() && !s.formulations.empty(), "scene without meshes or formulations");
  for (const SceneMesh& m : s.meshes) {
    require(!m.sizes.empty(), "mesh " + m.label + " without sizes");
    for (std::size_t i = 0; i < m.sizes.size(); ++i) {
      require(std::isfinite(m.sizes[i]) && m.sizes[i] > 0,
              "mesh " + m.label + " size " + std::to_string(m.sizes[i]));
      require(i == 0 || m.sizes[i] < m.sizes[i - 1], "mesh " + m.label + " sizes not decreasing");
    }
    require(m.realizations >= 1,
            "mesh " + m.label + " realizations " + std::to_string(m.realizations));
  }
  for (const SceneFormulation& f : s.formulations) {
    const int rule = f.settings.element.rule_points;
    require(rule == 1 || rule == 3 || rule == 6,
            "formulation " + f.label + " rule " + std::to_string(rule));
    require(f.settings.formulation == "cg" ? f.kp.empty() : !f.kp.empty(),
            "formulation " + f.label + " kp list");
    for (double k : f.kp)
      require(std::isfinite(k) && k > 0, "formulation " + f.label + " kp " + std::to_string(k));
  }
}

/// A static scene: its values, and its integers as written in the file.
void check_scene(const Scene& s, const std::string& text) {
  if (s.study == "extremes") {  // the sweeps are the scenes that run
    require(!s.sweeps.empty(), "extremes scene without sweeps");
    for (const auto& sweep : s.sweeps) check_values(*sweep);
    return;
  }
  check_values(s);
  const json root = json::parse(text);  // parse_scene accepted it, so it is valid JSON
  for (std::size_t i = 0; i < s.meshes.size(); ++i) {
    const json& m = root.at("meshes").at(i);
    const std::string where = "meshes[" + std::to_string(i) + "]";
    check_integer(m, "realizations", s.meshes[i].realizations, where);
    if (m.contains("seed"))
      require(m.at("seed").get<double>() == static_cast<double>(s.meshes[i].seed),
              where + ".seed written " + m.at("seed").dump() + ", accepted as " +
                  std::to_string(s.meshes[i].seed));
  }
  for (std::size_t i = 0; i < s.formulations.size(); ++i) {
    const json& f = root.at("formulations").at(i);
    const SolveSettings& settings = s.formulations[i].settings;
    const std::string where = "formulations[" + std::to_string(i) + "]";
    check_integer(f, "rule", settings.element.rule_points, where);
    check_integer(f, "refinement", settings.element.weights.refinement, where);
    check_integer(f, "degree", settings.element.weights.degree, where);
    check_integer(f, "max_iterations", settings.dg.max_iterations, where);
    check_integer(f, "sipg_sign", settings.dg.sipg_sign, where);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    read_study_scene(text, "fuzz.json");
    const std::string kind = scene_study(text, "fuzz.json");
    if (kind != "fracture" && kind != "dynamics" && kind != "fragmentation")
      check_scene(parse_scene(text, "fuzz.json", {kind == "extremes", kind == "trade-off"}), text);
  } catch (const InputError&) {
    // the correct answer to bad input
  } catch (const NumericalError&) {
  }
  return 0;
}
