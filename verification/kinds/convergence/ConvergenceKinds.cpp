// The convergence study and its two special cases: errors and rates over levels and
// realizations (convergence), over a list of k_p per DG formulation (penalty-sweep), and every
// formulation on affine fields judged pass or fail (patch-suite). One runner serves the three;
// each gives the report its own sections.
#include "verification/kinds/convergence/PatchSuiteReport.hpp"
#include "verification/kinds/convergence/PenaltyAnalysis.hpp"
#include "verification/static/KpTrendReport.hpp"
#include "verification/static/StaticStudy.hpp"

namespace vorodg {
namespace {

int run_convergence(const StudyCall& call) {
  return run_static_study(read_scene(call.scene), call);
}

/// The convergence tables, then the penalty analysis: per interface, the k_p where the DG
/// solution stops changing, and the sweep's rates side by side.
int penalty_sections(const ReportInput& in, std::ostringstream& md) {
  convergence_sections(in, md);
  write_penalty_analysis(in.scene, in.out, md);
  write_penalty_comparison(in.scene, in.records, md);
  return 0;
}

int run_penalty_sweep(const StudyCall& call) {
  return run_static_study(read_scene(call.scene), call, penalty_sections);
}

/// The verdict of every run against the expected outcome, instead of the convergence tables.
int patch_sections(const ReportInput& in, std::ostringstream& md) {
  const int unexpected = write_patch_suite(in.scene, in.records, md);
  write_kp_trend(in.summary, md);
  return unexpected;
}

int run_patch_suite(const StudyCall& call) {
  return run_static_study(read_scene(call.scene), call, patch_sections);
}

}  // namespace

StudyKind convergence_kind() {
  return {"convergence", "errors and rates over levels and realizations", static_scene_reader(),
          run_convergence, static_scene_keys};
}

StudyKind penalty_sweep_kind() {
  return {"penalty-sweep", "the same, over a list of k_p per DG formulation", static_scene_reader(),
          run_penalty_sweep, static_scene_keys};
}

StudyKind patch_suite_kind() {
  return {"patch-suite", "every formulation on affine fields: pass or fail against the expected",
          static_scene_reader(), run_patch_suite, static_scene_keys};
}

}  // namespace vorodg
