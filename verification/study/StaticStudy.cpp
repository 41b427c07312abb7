#include "verification/study/StaticStudy.hpp"

#include <algorithm>
#include <iostream>
#include <map>

#include "core/util/Stopwatch.hpp"
#include "verification/harness/Ensemble.hpp"
#include "verification/harness/PlotScript.hpp"
#include "verification/model/SettingsSchema.hpp"
#include "verification/study/StudyReport.hpp"

namespace vorodg {

StudyOptions study_options(const StudyCall& call) {
  StudyOptions options;
  options.out = call.out;
  options.threads = call.threads;
  options.progress = call.progress;
  return options;
}

int run_static_study(
    const Scene& scene, const StudyCall& call,
    const std::function<void(const std::vector<RunRecord>&, const StudyOptions&)>& check) {
  const Stopwatch clock;
  const StudyOptions options = study_options(call);
  const std::vector<RunRecord> results = run_study(scene, options);
  if (check) check(results, options);
  if (!Ensemble::writes_reports()) return 0;  // the reports are the coordinator's
  const StudyReport report = write_study_report(scene, results, call.out);
  if (!call.no_plots) draw_plots("plot_study.py", call.out);
  finish_report_markdown(report.markdown, call.out, study_pictures());
  std::cout << "\n"
            << scene.name << ": " << results.size() << " runs, " << clock.seconds()
            << " s; report in " << (call.out / "report.md").string() << "\n";
  if (report.unexpected > 0) {
    std::cerr << "vorodg: " << report.unexpected
              << " patch-suite outcomes differ from the expected ones\n";
    return 1;
  }
  return 0;
}

std::vector<SceneKey> static_scene_keys() {
  // The top-level `problems` is a list in a scene: the scene reader's, not the schema's.
  static const std::map<SettingScope, std::string> prefix = {
      {SettingScope::material, "material."},
      {SettingScope::formulation, "formulations[]."},
      {SettingScope::outputs, "outputs."}};
  static const std::map<SettingKind, std::string> type = {{SettingKind::number, "number"},
                                                          {SettingKind::integer, "integer"},
                                                          {SettingKind::flag, "bool"},
                                                          {SettingKind::choice, "string"}};
  std::vector<SceneKey> keys;
  for (const SettingSpec& spec : setting_specs()) {
    if (!prefix.count(spec.scope)) continue;  // command-line only
    keys.push_back(key(prefix.at(spec.scope) + spec.key, type.at(spec.kind), default_text(spec),
                       requirement_text(spec), spec.doc));
    SceneKey& k = keys.back();
    k.lower = spec.range.lower, k.upper = spec.range.upper;
    k.lower_open = spec.range.lower_open, k.upper_open = spec.range.upper_open;
    if (!spec.range.allowed.empty()) {  // a list of values: its least and greatest
      const auto [lo, hi] =
          std::minmax_element(spec.range.allowed.begin(), spec.range.allowed.end());
      k.lower = *lo, k.upper = *hi, k.lower_open = k.upper_open = false;
    }
  }
  return keys;
}

std::string read_static_scene(const std::string& text, const std::string& source) {
  return parse_scene(text, source).description;
}

}  // namespace vorodg
