#pragma once
// What a penalty study reports beside its runs (docs/dg.md "Penalty"): on realization 0 of every
// mesh level, the coercive penalty of every interface relative to E / h_avg against the edge's
// length (fan and point tractions), and the smallest fixed k_p (eps = k_p E / h_avg) for which
// the symmetric interior-penalty matrix is still positive definite, by bisection on k_p with a
// Cholesky attempt per step.
#include <filesystem>
#include <sstream>

#include "verification/solve/RunRecord.hpp"
#include "verification/static/Scene.hpp"

namespace vorodg {

/// Writes penalty_edges.csv and penalty_thresholds.csv into `out` and a section into `md`.
void write_penalty_analysis(const Scene& scene, const std::filesystem::path& out,
                            std::ostringstream& md);

/// Per mesh and level (realization 0), each dg-sipg reading at its cheapest working penalty: the
/// coercive ones at k_p = 1 (the proven bound), the fixed ones at the smallest k_p that solved,
/// with L2 error, condition estimate and time, into `md`.
void write_penalty_comparison(const Scene& scene, const std::vector<RunRecord>& records,
                              std::ostringstream& md);

}  // namespace vorodg
