#pragma once
// What a penalty study reports beside its runs (docs/dg.md "Penalty"): on realization 0 of every
// mesh level, the coercive penalty of every interface relative to E / h_avg against the edge's
// length (fan and point tractions), and the smallest fixed k_p (eps = k_p E / h_avg) for which
// the symmetric interior-penalty matrix is still positive definite, by bisection on k_p with a
// Cholesky attempt per step.
#include <filesystem>
#include <sstream>

#include "verification/study/Scene.hpp"

namespace vorodg {

/// Writes penalty_edges.csv and penalty_thresholds.csv into `out` and a section into `md`.
void write_penalty_analysis(const Scene& scene, const std::filesystem::path& out,
                            std::ostringstream& md);

}  // namespace vorodg
