#pragma once
// How an ensemble kind (fracture, dynamics, fragmentation) runs a scene: each part (the scene, or
// each of its variants) into its own folder, after a header and the echo of every key with the
// value used, then its plots; then one summary line. A run that broke down
// keeps what it wrote and is reported; the study then exits 3.
#include <filesystem>
#include <functional>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "core/schema/SceneKeyReader.hpp"
#include "core/util/Stopwatch.hpp"
#include "verification/harness/Ensemble.hpp"
#include "verification/harness/PlotScript.hpp"
#include "verification/harness/SceneVariants.hpp"
#include "verification/harness/StudyKind.hpp"

namespace vorodg {

/// What a part ran: how many runs, how many of them incomplete.
struct PartCounts {
  std::size_t runs = 0;
  int incomplete = 0;
};

/// Runs every part with `run_part(part, folder)`, drawing `plot_script` on each folder; then
/// `after` (on the process that reports). `what` names the runs in the closing message.
template <class SceneT>
int run_study_parts(
    const SceneT& scene, const StudyCall& call, const std::string& what,
    const std::string& plot_script,
    const std::function<PartCounts(const SceneT&, const std::filesystem::path&)>& run_part,
    const std::function<void(int incomplete)>& after = {}) {
  const Stopwatch clock;
  PartCounts total;
  for (const SceneT* part : study_parts(scene)) {
    const std::filesystem::path out = part_folder(call.out, part->label);
    std::cout << "\n== " << (part->label.empty() ? part->name : part->label) << "\n";
    echo_settings(part->settings);
    const PartCounts counts = run_part(*part, out);
    total.runs += counts.runs;
    total.incomplete += counts.incomplete;
    if (!call.no_plots && Ensemble::writes_reports()) draw_plots(plot_script, out);
  }
  if (!Ensemble::writes_reports()) return 0;  // the reports are the coordinator's
  if (after) after(total.incomplete);
  std::cout << "\n" << scene.name << ": " << total.runs << " runs, " << clock.seconds() << " s\n";
  if (total.incomplete == 0) return 0;
  std::cerr << "vorodg: " << total.incomplete << " " << what
            << " runs are incomplete (see report.md)\n";
  return 3;
}

}  // namespace vorodg
