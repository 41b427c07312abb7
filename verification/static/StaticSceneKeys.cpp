#include "verification/static/StaticSceneKeys.hpp"

#include "verification/harness/CommonKeys.hpp"
#include "verification/harness/StudyKind.hpp"
#include "verification/solve/SettingsSchema.hpp"
#include "verification/static/Scene.hpp"

namespace vorodg {
namespace {

/// The settings schema's keys of one scope, as scene keys under `prefix`.
std::vector<SceneKey> schema_keys(SettingScope scope, const std::string& prefix) {
  std::vector<SceneKey> keys;
  for (const SettingSpec& spec : setting_specs()) {
    if (spec.scope != scope) continue;
    SceneKey row = spec;  // the setting's own row, under the scope's prefix
    row.name = prefix + spec.name;
    // nu and k_p may be lists in a scene: one run per value (read_material, read_formulation).
    if (spec.name == "nu" || spec.name == "kp") row.type = "number or list";
    keys.push_back(row);
  }
  return keys;
}

/// study, problems, domain: what a static scene is about.
std::vector<SceneKey> static_study_keys() {
  std::string kinds;
  for (const StudyKind& k : study_kinds()) kinds += (kinds.empty() ? "" : ", ") + k.name;
  const SettingSpec& problem = setting_spec("problem");
  return {key("study", "string", Scene{}.study, kinds,
              "the study kind (fracture, dynamics and fragmentation have tables of their own)"),
          key("problems", "string or list", SolveSettings{}.problem, problem.range,
              "the exact solutions every mesh and formulation is run on (a problem with no "
              "Dirichlet side is refused: every run would be singular)"),
          key("domain", "[x0, y0, x1, y1]", "beam: [0, -0.5, 4, 0.5]; else [0, 0, 2, 1]",
              kRectangleRange, "the rectangle; the beam needs [0, L] x [-D/2, D/2]")};
}

/// patch_tolerance, reference and the trade-off's knobs.
std::vector<SceneKey> report_keys() {
  const Scene scene;
  const TradeoffSettings t;
  return {
      bounded("patch_tolerance", "number", exact_text(scene.patch_tolerance), "0 < tol <= 1",
              "patch-suite: relative errors at most this pass", 0.0, true, 1.0),
      key("reference", "string", "\"\"", "a key of data/reference/published.json",
          "published rates and trends shown beside ours"),
      bounded("tradeoff.rate_tolerance", "number", exact_text(t.rate_tolerance), "0 < tol < 1",
              "trade-off: a configuration enters the front only if its least-squares L2 and "
              "energy rates are within this fraction of 2 and 1",
              0.0, true, 1.0, true),
      bounded("tradeoff.min_seconds", "number", exact_text(t.min_seconds), "0 <= s <= 1e6",
              "trade-off: levels whose median run takes at least this are timed; only they enter "
              "the error-cost lines and the front",
              0.0, false, 1e6),
      bounded("tradeoff.targets", "list of numbers",
              "three decades down to the power of ten at or below the best finest-level L2 error",
              "each 0 < e <= 1e6", "trade-off: the L2 errors the recommendation is given for", 0.0,
              true, 1e6),
      key("tradeoff.verify", "bool", t.verify ? "true" : "false", "true or false",
          "trade-off: run the recommendation for the smallest target again at its predicted mesh "
          "size, into DIR/verification/"),
      bounded("tradeoff.verification_realizations", "integer",
              std::to_string(t.verification_realizations), "1 <= n <= 1000",
              "trade-off: the runs of that check (their median time is compared)", 1.0, false,
              1000.0),
  };
}

/// sweeps[]: the extremes study's axes, each a scene merged over the top level.
std::vector<SceneKey> static_sweep_keys() {
  const Scene d;  // a sweep is a Scene: its defaults
  return {
      key("sweeps[]", "list (required)", "", "a non-empty list of sweep objects",
          "extremes: one block per sweep, each merged over the top-level keys (JSON merge patch: "
          "objects merge key by key, lists are replaced)"),
      key("sweeps[].name", "string (required)", "", "a folder name: no /, \\, spaces; unique",
          "the sweep's folder under -o DIR"),
      key("sweeps[].axis", "string (required)", "", choice_list(sweep_axis_choices()),
          "what the sweep varies (aspect: L/D of the domain; h: h_avg)"),
      key("sweeps[].baseline", "string", d.baseline, choice_list(baseline_choices()),
          "what an error is compared with"),
      bounded("sweeps[].expected_rate", "number", exact_text(d.expected_rate), "0 < rate <= 10",
              "coarsest-level: the rate the error should fall at", 0.0, true, 10.0),
      bounded("sweeps[].degraded_factor", "number", exact_text(d.degraded_factor),
              "1 < factor <= 1e12, below broken_factor",
              "an error above this times the baseline: degraded", 1.0, true, 1e12),
      bounded("sweeps[].broken_factor", "number", exact_text(d.broken_factor),
              "1 < factor <= 1e12, above degraded_factor",
              "an error above this times the baseline: broken", 1.0, true, 1e12),
  };
}

std::vector<SceneKey> make_static_keys(bool sweeps) {
  std::vector<SceneKey> keys = naming_keys();
  append_keys(keys, static_study_keys());
  append_keys(keys, schema_keys(SettingScope::material, "material."));
  append_keys(keys, mesh_keys());
  keys.push_back(key("formulations[]", "list (required)", "",
                     "a non-empty list of formulation blocks",
                     "one block per formulation; `label` names it in reports (default: the name "
                     "and the knobs that differ)"));
  append_keys(keys, schema_keys(SettingScope::formulation, "formulations[]."));
  append_keys(keys, schema_keys(SettingScope::outputs, "outputs."));
  append_keys(keys, report_keys());
  if (sweeps) append_keys(keys, static_sweep_keys());
  return keys;
}

}  // namespace

const KeyTable& static_scene_table() {
  static const KeyTable table{"static", make_static_keys(false), {}};
  return table;
}

const KeyTable& extremes_scene_table() {
  static const KeyTable table{"extremes", make_static_keys(true), {}};
  return table;
}

std::vector<SceneKey> static_scene_keys() {
  return static_scene_table().keys;
}

std::vector<SceneKey> extremes_scene_keys() {
  return extremes_scene_table().keys;
}

const SceneKey& static_key(const std::string& name) {
  return extremes_scene_table().at(name);
}

}  // namespace vorodg
