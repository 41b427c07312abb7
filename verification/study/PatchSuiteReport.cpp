#include "verification/study/PatchSuiteReport.hpp"

#include <iostream>

#include "verification/report/ConvergenceTable.hpp"

namespace vorodg {

bool expected_to_pass(const Scene& scene, const StudyRun& run) {
  if (run.formulation_name == "dg-penalty") return false;
  if (!scene.formulations[run.formulation].settings.element.divergence_correction)
    return run.family == MeshFamily::tri || run.family == MeshFamily::quad;
  return true;
}

int write_patch_suite(const Scene& scene, const std::vector<RunRecord>& records,
                      std::ostringstream& md) {
  ConvergenceTable table;
  const ConvergenceTable::Style sci{3, true};
  int unexpected = 0;
  for (const RunRecord& r : records) {
    const auto& m = r.metrics;
    const bool pass =
        m && m->l2_error <= scene.patch_tolerance && m->energy_error <= scene.patch_tolerance;
    const bool expect = expected_to_pass(scene, r.run);
    unexpected += pass != expect;
    table.start_row();
    table.add_text("run", r.run.id);
    if (m) {
      table.add_value("L2 error", m->l2_error, std::nullopt, sci);
      table.add_value("energy error", m->energy_error, std::nullopt, sci);
    }
    table.add_text("verdict", !m ? "failed to run" : pass ? "pass" : "fail");
    table.add_text("expected", std::string(expect ? "pass" : "fail") +
                                   (pass == expect ? "" : " **unexpected**"));
  }
  std::cout << "patch suite (tolerance " << scene.patch_tolerance << "):\n";
  table.write_text(std::cout);
  table.write_markdown(md);
  md << "\n" << unexpected << " outcomes differ from the expected ones.\n";
  return unexpected;
}

}  // namespace vorodg
