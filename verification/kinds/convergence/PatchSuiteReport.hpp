#pragma once
// The patch-suite verdicts: every run passes when both its errors are at most the scene's
// patch tolerance; each verdict is compared with what the formulation is expected to do.
#include <sstream>
#include <vector>

#include "verification/solve/RunRecord.hpp"
#include "verification/static/Scene.hpp"

namespace vorodg {

/// What a run of the patch suite is expected to do.
enum class PatchOutcome { pass, fail, refused };

/// Every formulation and element passes but dg-penalty (which is inconsistent); without the
/// divergence correction, only on triangles and squares. The Wachspress element refuses the
/// meshes that can have non-convex cells (perturbed hexagons, regularized rcp).
PatchOutcome expected_outcome(const Scene& scene, const StudyRun& run);

/// Prints the verdicts, appends their table to `md` and returns the number of unexpected ones.
int write_patch_suite(const Scene& scene, const std::vector<RunRecord>& records,
                      std::ostringstream& md);

}  // namespace vorodg
