// The explicit-dynamics studies: `dynamics` (wave bars, free bodies, impacts: every measured
// figure beside its theory) and `fragmentation`, the same with crack insertion and the cohesive
// law (fragment counts, masses, the energy with the law's closed forms). One reader and one
// runner serve both; each variant, or each value of a `perturb` study, runs into its own
// subfolder, and a perturbation study ends with the Hamming distances between them.
#include "verification/dynamics/DynamicsKeys.hpp"
#include "verification/dynamics/DynamicsStudy.hpp"
#include "verification/dynamics/PerturbationReport.hpp"
#include "verification/harness/StudyParts.hpp"

namespace vorodg {
namespace {

int run_dynamics_scene(const StudyCall& call) {
  const DynamicsScene scene = read_dynamics_scene(call.scene, call.force);
  return run_study_parts<DynamicsScene>(
      scene, call, "dynamics", "dynamics_plots.py",
      [&](const DynamicsScene& part, const std::filesystem::path& out) {
        const DynamicsStudyResult r = run_dynamics_study(part, out, call.threads, call.progress);
        return PartCounts{r.records.size(), r.incomplete};
      },
      [&](int incomplete) {
        if (!scene.perturb_key.empty() && incomplete == 0)
          write_perturbation_report(scene, call.out);
        if (scene.fragmentation && scene.variants.size() >= 2 && !call.no_plots)
          draw_plots("dynamics_plots.py", call.out);  // across the variants, and the perturbation
      });
}

/// Reads as `vorodg run --force` would: --list and the fuzzer take every scene a run can take.
std::string read_dynamics(const std::string& text, const std::string& source) {
  return parse_dynamics_scene(text, source, true).description;
}

std::vector<SceneKey> dynamics_keys() {
  return dynamics_scene_keys().keys;
}

}  // namespace

StudyKind dynamics_kind() {
  return {"dynamics",
          "explicit dynamics with contact: waves, free bodies, impacts against their theory",
          read_dynamics, run_dynamics_scene, dynamics_keys};
}

StudyKind fragmentation_kind() {
  return {"fragmentation",
          "explicit dynamics with crack insertion: fragments, their masses and the energy",
          read_dynamics, run_dynamics_scene, dynamics_keys};
}

}  // namespace vorodg
