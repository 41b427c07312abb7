#pragma once
// The stable time step of central differences with lumped masses (report section 6).
//
// Per cell, lambda_c is the largest eigenvalue of M_c^-1 K_c, where K_c is the cell stiffness
// and M_c the diagonal of the cell's own pair masses (each twice, for x and y). The global
// lambda_max of M^-1 K is bounded by max_c lambda_c for any DOF map: the Rayleigh quotient
// u.K u / u.M u = sum_c u_c.K_c u_c / sum_c u_c.M_c u_c is a ratio of sums of non-negative
// terms, hence at most the largest cell ratio (element eigenvalue inequality). So
//     dt_crit = 2 / sqrt(max_c lambda_c)
// is conservative: never above the true critical step of the assembled system.
//
// Solver: exact, not power iteration. Cells have at most some 20 DOFs, and with a diagonal M_c
// the generalized problem K x = lambda M x is the symmetric one of M^-1/2 K M^-1/2 (what
// Eigen's GeneralizedSelfAdjointEigenSolver reduces to after its Cholesky factor of M, which
// for a diagonal M is this scaling). A dense symmetric eigensolve of 2n <= 20 costs
// microseconds, is exact to round-off whatever the eigenvalue gap (power iteration converges
// slowly when the top two are close, as they often are by symmetry), and is deterministic.
//
// A tighter bound that is just as safe weights the cell eigenvalues per node. Continuing the
// Rayleigh quotient, sum_c u_c.K_c u_c <= sum_c lambda_c u_c.M_c u_c = sum_i |u_i|^2 sum_{(c,k) at
// i} lambda_c m_{c,k}, so lambda_max <= max_i (sum_{(c,k) at i} lambda_c m_{c,k}) / m_i: at each
// node the pair-mass-weighted mean of its cells' eigenvalues. A stiff cell among softer ones no
// longer sets the step alone. It depends on the DOF map (for the fully split map it is the cell
// bound). Both are far below the true step on random meshes (docs/dynamics.md); GlobalTimeStep
// estimates the true one.
//
// Mass-proportional damping (c M v, with the velocity at the step taken centred as in
// CentralDifference) does not change this limit. Bulk viscosity, taken from the half-step
// velocities, does: BulkViscosity::step_factor.
#include <Eigen/Core>
#include <vector>

#include "core/dofs/SplitDofMap.hpp"
#include "core/element/ElasticityIntegrator.hpp"
#include "core/mesh/PolygonMesh.hpp"
#include "dynamics/LumpedMass.hpp"

namespace vorodg {

class StableTimeStep {
 public:
  static constexpr double kDefaultSafety = 0.9;

  /// `matrices` holds every cell of `mesh`. Cells are solved in parallel into their own slots,
  /// so the result does not depend on `threads`. Throws NumericalError naming the cell if a
  /// cell's largest eigenvalue is not positive and finite.
  StableTimeStep(const PolygonMesh& mesh, const ElasticityIntegrator::CellMatrices& matrices,
                 const LumpedMass& mass, int threads = 1);

  /// Largest eigenvalue of M_c^-1 K_c of one cell: K (2n x 2n), masses of its n pairs.
  static double cell_eigenvalue(const Eigen::MatrixXd& K, const Eigen::VectorXd& pair_masses);

  /// 2 / sqrt(max_c lambda_c), never above the true critical step of the assembled system.
  double critical() const { return critical_; }
  /// safety x critical(); throws InputError unless 0 < safety <= 1.
  double step(double safety = kDefaultSafety) const;
  /// The node-weighted bound for a DOF map of the mesh (>= critical(), still conservative).
  double nodal_critical(const SplitDofMap& dofs, const LumpedMass& mass) const;
  /// The cell whose eigenvalue sets critical().
  int controlling_cell() const { return controlling_; }
  double max_eigenvalue() const { return max_lambda_; }
  double cell_eigenvalue(int c) const { return lambda_[c]; }

 private:
  std::vector<double> lambda_;
  double max_lambda_ = 0.0;
  double critical_ = 0.0;
  int controlling_ = -1;
};

}  // namespace vorodg
