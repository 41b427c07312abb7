// The extremes study: sweeps to the numerical extremes (nu, k_p, aspect ratio, perturbation,
// regularization, h), each run and reported in a subfolder, then a verdict per run against the
// sweep's baseline (ExtremesReport). Broken runs are findings of the study, not a failure of
// the program: it exits 0.
#include <iostream>

#include "core/util/Stopwatch.hpp"
#include "verification/harness/Ensemble.hpp"
#include "verification/harness/PlotScript.hpp"
#include "verification/kinds/extremes/ExtremesReport.hpp"
#include "verification/static/StaticStudy.hpp"
#include "verification/static/StudyReport.hpp"

namespace vorodg {
namespace {

constexpr StaticSceneForm kExtremesForm{true, false};  // a list of sweeps

int run_extremes(const StudyCall& call) {
  const Stopwatch clock;
  const Scene scene = read_scene(call.scene, kExtremesForm);
  std::vector<std::vector<RunRecord>> results;
  std::size_t runs = 0;
  for (const auto& sweep : scene.sweeps) {
    StudyOptions sub = study_options(call);
    sub.out = call.out / sweep->name;
    std::cout << "\n== sweep " << sweep->name << " (" << sweep->axis << ")\n";
    results.push_back(run_study(*sweep, sub));
    if (!Ensemble::writes_reports()) continue;  // the reports are the coordinator's
    // A sweep's own report has no pictures: the extremes plot stands for them all.
    finish_report_markdown(write_study_report(*sweep, results.back(), sub.out).markdown, sub.out,
                           {});
    runs += results.back().size();
  }
  if (!Ensemble::writes_reports()) return 0;
  std::string markdown;
  const int broken = write_extremes_report(scene, results, call.out, markdown);
  if (!call.no_plots) draw_plots("plot_study.py", call.out);
  finish_report_markdown(markdown, call.out, study_pictures());
  std::cout << "\n"
            << scene.name << ": " << runs << " runs (" << broken << " broken), " << clock.seconds()
            << " s; report in " << (call.out / "report.md").string() << "\n";
  return 0;
}

}  // namespace

StudyKind extremes_kind() {
  return {"extremes", "sweeps to the numerical extremes, a verdict per run",
          static_scene_reader(kExtremesForm), run_extremes, extremes_scene_keys};
}

}  // namespace vorodg
