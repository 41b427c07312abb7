#include "core/solve/LinearSolverChoice.hpp"

#include <algorithm>

#include "core/solve/AmgConjugateGradient.hpp"

namespace vorodg {

LinearSolverKind resolve_solver(LinearSolverKind kind, long free_dofs) {
  if (kind != LinearSolverKind::automatic) return kind;
  return free_dofs >= kAmgFromFreeDofs && AmgConjugateGradient::available()
             ? LinearSolverKind::amg_cg
             : LinearSolverKind::cholmod;
}

double amg_tolerance_for(double h_avg, double length) {
  const double relative_h = h_avg / length;
  return std::clamp(0.01 * relative_h * relative_h, 1e-12, 1e-6);
}

}  // namespace vorodg
