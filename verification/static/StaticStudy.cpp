#include "verification/static/StaticStudy.hpp"

#include <algorithm>
#include <iostream>

#include "core/util/Stopwatch.hpp"
#include "verification/harness/Ensemble.hpp"
#include "verification/harness/PlotScript.hpp"
#include "verification/solve/SettingsSchema.hpp"
#include "verification/static/StudyReport.hpp"

namespace vorodg {

StudyOptions study_options(const StudyCall& call) {
  StudyOptions options;
  options.out = call.out;
  options.threads = call.threads;
  options.progress = call.progress;
  return options;
}

int run_static_study(
    const Scene& scene, const StudyCall& call, const ReportSections& sections,
    const std::function<void(const std::vector<RunRecord>&, const StudyOptions&)>& check) {
  const Stopwatch clock;
  const StudyOptions options = study_options(call);
  const std::vector<RunRecord> results = run_study(scene, options);
  if (check) check(results, options);
  if (!Ensemble::writes_reports()) return 0;  // the reports are the coordinator's
  const StudyReport report = write_study_report(scene, results, call.out, sections);
  if (!call.no_plots) draw_plots("plot_study.py", call.out);
  finish_report_markdown(report.markdown, call.out, study_pictures());
  std::cout << "\n"
            << scene.name << ": " << results.size() << " runs, " << clock.seconds()
            << " s; report in " << (call.out / "report.md").string() << "\n";
  if (report.unexpected > 0) {
    std::cerr << "vorodg: " << report.unexpected
              << " outcomes differ from the expected ones (see report.md)\n";
    return 1;
  }
  return 0;
}

std::function<std::string(const std::string&, const std::string&)> static_scene_reader(
    StaticSceneForm form) {
  return [form](const std::string& text, const std::string& source) {
    return parse_scene(text, source, form).description;
  };
}

}  // namespace vorodg
