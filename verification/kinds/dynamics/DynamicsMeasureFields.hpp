#pragma once
// The figures a dynamics run measures (DynamicsMeasures), by the names results.csv, summary.json
// and the time-refinement report give them, in results.csv's order.
#include <utility>
#include <vector>

#include "dynamics/problems/DynamicsProbe.hpp"

namespace vorodg {

const std::vector<std::pair<const char*, double DynamicsMeasures::*>>& dynamics_measure_fields();

}  // namespace vorodg
