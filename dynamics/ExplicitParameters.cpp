#include "dynamics/ExplicitParameters.hpp"

#include <algorithm>
#include <cmath>

#include "dynamics/BodiesMesh.hpp"

namespace vorodg {

std::string step_estimate_name(StepEstimate e) {
  return e == StepEstimate::lanczos ? "lanczos" : "cells";
}

double ExplicitParameters::bar_speed() const {
  return std::sqrt(E / (density * (plane == PlaneModel::stress ? 1.0 : 1.0 - nu * nu)));
}

double ExplicitParameters::dilatational_speed() const {
  if (plane == PlaneModel::stress) return std::sqrt(E / (density * (1.0 - nu * nu)));
  return std::sqrt(E * (1.0 - nu) / (density * (1.0 + nu) * (1.0 - 2.0 * nu)));
}

int BodiesMesh::body_of_cell(int c) const {
  const auto it = std::upper_bound(first_cell.begin(), first_cell.end(), c);
  return static_cast<int>(it - first_cell.begin()) - 1;
}

}  // namespace vorodg
