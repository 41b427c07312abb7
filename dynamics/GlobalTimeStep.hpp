#pragma once
// The critical step of the assembled system, estimated by Lanczos iteration on
// M^-1/2 K M^-1/2 (K applied cell by cell through InternalForce, never formed).
//
// Why: the cell-by-cell bound (StableTimeStep) is safe for any DOF map but far below the true
// critical step on random meshes: 0.53 of it on a small rcp mesh, where the controlling cell
// has an edge of 0.12 d next to the domain boundary and its neighbours, which the cell bound
// leaves out, carry much of its nodes' mass (docs/dynamics.md). Lanczos converges to the top
// eigenvalue in tens of force evaluations, each the cost of one time step.
//
// Safety: the top Ritz value theta is a lower bound of lambda_max, and some eigenvalue lies
// within the residual r = beta_k |s_k| of it. With a random start vector the top Ritz value
// converges to lambda_max, so lambda = min(theta + r, cell bound) is used: an upper bound of
// lambda_max unless the start vector misses the top eigenvector (probability zero), and never
// looser than the cell bound. It holds for the DOF map it was computed on only: splitting nodes
// raises lambda_max (towards the cell bound for a fully split mesh), so recompute after a remap.
//
// Deterministic: the start vector comes from a seeded Random, the dot products are serial and
// InternalForce is thread-count independent, so the estimate does not depend on threads.
#include <Eigen/Core>
#include <cstdint>
#include <functional>

#include "dynamics/InterfaceCoupling.hpp"
#include "dynamics/InternalForce.hpp"
#include "dynamics/StableTimeStep.hpp"

namespace vorodg {

struct LanczosOptions {
  double tolerance = 1e-3;  // stop when r / theta is below it
  int max_iterations = 300;
  std::uint64_t seed = 1;
  int threads = 1;
};

class GlobalTimeStep {
 public:
  /// `node_masses` are the per-node masses of `dofs`; the force's last-compute buffers are
  /// overwritten. `bound` caps the eigenvalue. With `coupling` (built on `dofs`), the system is
  /// the cells' and the coupled interfaces' together, and the cap adds the interfaces' bound.
  GlobalTimeStep(InternalForce& force, const SplitDofMap& dofs, const Eigen::VectorXd& node_masses,
                 const StableTimeStep& bound, const LanczosOptions& options = {},
                 const InterfaceCoupling* coupling = nullptr);
  /// K x -> stiffness(x, Kx) for a stiffness K of any make (Kx is overwritten).
  using Stiffness = std::function<void(const Eigen::VectorXd& x, Eigen::VectorXd& Kx)>;
  /// The same estimate for a stiffness given as a product, on the DOFs of `node_masses` (x, y per
  /// node); `cap` is an upper bound of its largest eigenvalue (a proven bound: the estimate is
  /// never looser than it).
  GlobalTimeStep(const Stiffness& stiffness, const Eigen::VectorXd& node_masses, double cap,
                 const LanczosOptions& options = {});

  /// 2 / sqrt(lambda), lambda = min(theta + r, cap): the cap is the cell bound (plus the
  /// interfaces') for the first constructor.
  double critical() const { return critical_; }
  /// safety x critical(); throws InputError unless 0 < safety <= 1.
  double step(double safety = StableTimeStep::kDefaultSafety) const;
  double ritz_value() const { return theta_; }
  double residual() const { return residual_; }
  int iterations() const { return iterations_; }
  bool converged() const { return converged_; }

 private:
  double theta_ = 0.0, residual_ = 0.0, critical_ = 0.0;
  int iterations_ = 0;
  bool converged_ = false;
};

}  // namespace vorodg
