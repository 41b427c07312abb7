#include "verification/kinds/convergence/PatchSuiteReport.hpp"

#include <iostream>

#include "verification/report/ConvergenceTable.hpp"

namespace vorodg {

namespace {

const char* outcome_name(PatchOutcome o) {
  return o == PatchOutcome::pass ? "pass" : o == PatchOutcome::fail ? "fail" : "refused";
}

/// What the run did: passed, failed (including a breakdown), or refused its mesh as input.
PatchOutcome outcome(const Scene& scene, const RunRecord& r) {
  const auto& m = r.metrics;
  if (!m)
    return r.error.find(kNotConvexCell) != std::string::npos ? PatchOutcome::refused
                                                             : PatchOutcome::fail;
  return m->l2_error <= scene.patch_tolerance && m->energy_error <= scene.patch_tolerance
             ? PatchOutcome::pass
             : PatchOutcome::fail;
}

}  // namespace

PatchOutcome expected_outcome(const Scene& scene, const StudyRun& run) {
  const ElementOptions& element = scene.formulations[run.formulation].settings.element;
  const SceneMesh& mesh = scene.meshes[run.mesh];
  const bool may_be_non_convex =
      (run.family == MeshFamily::perturbed_hex && mesh.perturbation > 0.0) ||
      (run.family == MeshFamily::rcp && mesh.regularization > 0.0);
  if (element.family == ElementFamily::wachspress && may_be_non_convex)
    return PatchOutcome::refused;
  if (run.formulation_name == "dg-penalty") return PatchOutcome::fail;
  if (!element.divergence_correction)
    return run.family == MeshFamily::tri || run.family == MeshFamily::quad ? PatchOutcome::pass
                                                                           : PatchOutcome::fail;
  return PatchOutcome::pass;
}

int write_patch_suite(const Scene& scene, const std::vector<RunRecord>& records,
                      std::ostringstream& md) {
  ConvergenceTable table;
  const ConvergenceTable::Style sci{3, true};
  int unexpected = 0;
  for (const RunRecord& r : records) {
    const auto& m = r.metrics;
    const PatchOutcome got = outcome(scene, r);
    const PatchOutcome expect = expected_outcome(scene, r.run);
    unexpected += got != expect;
    table.start_row();
    table.add_text("run", r.run.id);
    if (m) {
      table.add_value("L2 error", m->l2_error, std::nullopt, sci);
      table.add_value("energy error", m->energy_error, std::nullopt, sci);
    }
    table.add_text("verdict", got == PatchOutcome::refused ? "refused"
                              : !m                         ? "failed to run"
                                                           : outcome_name(got));
    table.add_text("expected",
                   std::string(outcome_name(expect)) + (got == expect ? "" : " **unexpected**"));
  }
  std::cout << "patch suite (tolerance " << scene.patch_tolerance << "):\n";
  table.write_text(std::cout);
  table.write_markdown(md);
  md << "\n" << unexpected << " outcomes differ from the expected ones.\n";
  return unexpected;
}

}  // namespace vorodg
