// The convergence study and its two special cases: errors and rates over levels and
// realizations (convergence), over a list of k_p per DG formulation (penalty-sweep), and every
// formulation on affine fields judged pass or fail (patch-suite). One runner serves the three;
// the report picks its tables by the scene's study (StudyReport).
#include "verification/study/StaticStudy.hpp"

namespace vorodg {
namespace {

int run_convergence(const StudyCall& call) {
  return run_static_study(read_scene(call.scene), call);
}

}  // namespace

StudyKind convergence_kind() {
  return {"convergence", "errors and rates over levels and realizations", read_static_scene,
          run_convergence, static_scene_keys};
}

StudyKind penalty_sweep_kind() {
  return {"penalty-sweep", "the same, over a list of k_p per DG formulation", read_static_scene,
          run_convergence, static_scene_keys};
}

StudyKind patch_suite_kind() {
  return {"patch-suite", "every formulation on affine fields: pass or fail against the expected",
          read_static_scene, run_convergence, static_scene_keys};
}

}  // namespace vorodg
