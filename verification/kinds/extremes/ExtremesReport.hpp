#pragma once
// The extremes study: every run of every sweep gets a verdict (ok / degraded / broken) with its
// reason, and the report states per axis and formulation the range of values that can be
// trusted. Verdicts, in order:
//   broken    the run broke down (its error message), a non-finite error, a DG iteration that
//             did not converge, a relative L2 error >= 1, or an error above broken_factor times
//             the baseline;
//   degraded  an error above degraded_factor times the baseline, a factor condition estimate
//             below 1e-12, or a DG iteration that needed more than half its allowed steps;
//   ok        otherwise.
// The baseline of a run is the same run with the sweep's reference setting (Scene::baseline):
// the first nu, the cg formulation, the sweep's first mesh, or the coarsest level scaled by
// (h / h_0)^expected_rate.
#include <filesystem>
#include <string>
#include <vector>

#include "verification/solve/RunRecord.hpp"
#include "verification/static/Scene.hpp"

namespace vorodg {

struct RunVerdict {
  std::string level;   // ok | degraded | broken
  std::string reason;  // empty for ok
};

/// The verdict of one run of a sweep, given the sweep's other runs (for the baseline).
RunVerdict judge_run(const Scene& sweep, const RunRecord& run, const std::vector<RunRecord>& runs);

/// The value of the sweep's axis for a run (nu, k_p, L/D, r, regularization threshold, h_avg).
double axis_value(const Scene& sweep, const RunRecord& run);

/// Writes extremes.csv and extremes.json (deterministic) into `out`, and prints the
/// trust table. `results[i]` are the runs of `scene.sweeps[i]`. Returns the number of broken
/// runs; `markdown` receives report.md's text (its picture is linked once drawn).
int write_extremes_report(const Scene& scene, const std::vector<std::vector<RunRecord>>& results,
                          const std::filesystem::path& out, std::string& markdown);

}  // namespace vorodg
