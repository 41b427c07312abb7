// The stable time step of central differences with lumped masses (dynamics/StableTimeStep):
//   - the per-cell eigenvalue equals the generalized eigenvalue of (K_c, M_c) from Eigen's
//     GeneralizedSelfAdjointEigenSolver, to 1e-10 relative;
//   - on every family, standard and mean dilation, against the true critical step
//     2 / sqrt(lambda_max(M^-1 K)) of the assembled free body (dense eigensolve): the cell-by-cell
//     bound and the node-weighted bound never exceed it (their ratios, printed, are 0.53 to 0.85:
//     the 10% target is out of their reach, docs/dynamics.md); the Lanczos estimate
//     (GlobalTimeStep) does not exceed it and is within 10% below it;
//   - on a free rcp body with a random initial displacement (fixed seed), the true critical step
//     found by bisection on whether the energy grows a millionfold within 2000 steps agrees with
//     the eigenvalue to 1e-3 and the Lanczos estimate is within 10% below it; at 0.9 x either
//     estimate the energy stays bounded and the discrete balance closes; at 1.1 x the true
//     critical step the run blows up.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>

#include "core/util/Errors.hpp"
#include "dynamics/GlobalTimeStep.hpp"
#include "support/DynamicsModel.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;

const IsotropicElasticity kMaterial(1.0, 0.3, PlaneModel::strain);

/// 2 / sqrt(largest eigenvalue of M^-1 K) of the assembled continuous free body.
double true_critical_step(const DynamicsModel& model) {
  const SplitDofMap dofs = SplitDofMap::continuous(model.mesh);
  const Eigen::VectorXd m = model.mass.node_masses(dofs);
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(dofs.num_dofs(), dofs.num_dofs());
  for (int c = 0; c < model.mesh.num_cells(); ++c) {
    const int n = model.mesh.cell_size(c);
    const auto Kc = model.matrices.block(c, 2 * n);
    for (int a = 0; a < 2 * n; ++a)
      for (int b = 0; b < 2 * n; ++b)
        K(2 * dofs.node(c, a / 2) + a % 2, 2 * dofs.node(c, b / 2) + b % 2) += Kc(a, b);
  }
  Eigen::VectorXd s(dofs.num_dofs());
  for (int i = 0; i < dofs.num_dofs(); ++i) s[i] = 1.0 / std::sqrt(m[i / 2]);
  const Eigen::MatrixXd A = s.asDiagonal() * (0.5 * (K + K.transpose())) * s.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(A, Eigen::EigenvaluesOnly);
  return 2.0 / std::sqrt(eig.eigenvalues().maxCoeff());
}

struct Outcome {
  bool blown = false;
  double max_growth = 0.0;     // largest (kinetic + elastic) / initial
  double balance_drift = 0.0;  // |balance - initial| / initial energy, largest
};

/// A free body from a random displacement at rest, for `steps` steps of size dt.
Outcome free_vibration(const DynamicsModel& model, double dt, int steps) {
  auto run = model.integrator_with(dt);
  const int n = run->dofs().num_dofs();
  run->initialize(random_vector(n, 1e-3, 99), Eigen::VectorXd::Zero(n));
  const double e0 = run->record().kinetic + run->record().elastic;
  Outcome out;
  for (int i = 0; i < steps; ++i) {
    const StepRecord& r = run->step();
    const double growth = (r.kinetic + r.elastic) / e0;
    out.max_growth = std::max(out.max_growth, growth);
    out.balance_drift = std::max(out.balance_drift, std::abs(r.balance() - r.initial_balance) / e0);
    if (!std::isfinite(growth) || growth > 1e6) {
      out.blown = true;
      break;
    }
  }
  return out;
}

TEST(StableTimeStep, CellEigenvalueMatchesTheGeneralizedSolver) {
  const DynamicsModel model(mesh_spec(MeshFamily::rcp, Rectangle(0, 0, 1, 1), 0.1), kMaterial, 2.0);
  for (int c = 0; c < model.mesh.num_cells(); c += 5) {
    const int n = model.mesh.cell_size(c);
    const Eigen::MatrixXd K = model.matrices.block(c, 2 * n);
    Eigen::VectorXd pairs(n), diag(2 * n);
    for (int k = 0; k < n; ++k)
      pairs[k] = diag[2 * k] = diag[2 * k + 1] = model.mass.pair_mass(c, k);
    const Eigen::MatrixXd M = diag.asDiagonal();
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(0.5 * (K + K.transpose()),
                                                                        M, Eigen::EigenvaluesOnly);
    const double expected = eig.eigenvalues().maxCoeff();
    EXPECT_NEAR(StableTimeStep::cell_eigenvalue(K, pairs), expected, 1e-10 * expected) << c;
    EXPECT_EQ(model.limit.cell_eigenvalue(c), StableTimeStep::cell_eigenvalue(K, pairs));
  }
  EXPECT_THROW(model.limit.step(0.0), InputError);
  EXPECT_THROW(model.limit.step(1.5), InputError);
  EXPECT_EQ(model.limit.step(), 0.9 * model.limit.critical());
}

TEST(StableTimeStep, EstimateIsConservativeAndWithinTenPercentOnEveryFamily) {
  struct Case {
    const char* name;
    MeshFamily family;
    double size;
  };
  const Case cases[] = {{"rcp", MeshFamily::rcp, 0.1},
                        {"hex", MeshFamily::hex, 0.1},
                        {"perturbed-hex", MeshFamily::perturbed_hex, 0.1},
                        {"tri", MeshFamily::tri, 0.1},
                        {"quad", MeshFamily::quad, 0.1}};
  for (const Case& k : cases) {
    for (bool mean_dilation : {false, true}) {
      const DynamicsModel model(mesh_spec(k.family, Rectangle(0, 0, 1, 1), k.size), kMaterial, 1.0,
                                mean_dilation);
      const double exact = true_critical_step(model);
      const double ratio = model.limit.critical() / exact;
      const SplitDofMap dofs = SplitDofMap::continuous(model.mesh);
      const double nodal = model.limit.nodal_critical(dofs, model.mass) / exact;
      InternalForce force(model.mesh, model.matrices);
      const GlobalTimeStep global(force, dofs, model.mass.node_masses(dofs), model.limit);
      const double lanczos = global.critical() / exact;
      std::printf(
          "%-14s %s %4d cells: estimate / true critical step: cell bound %.4f, nodal "
          "bound %.4f, Lanczos %.4f (%d iterations)\n",
          k.name, mean_dilation ? "mean-dilation" : "standard     ", model.mesh.num_cells(), ratio,
          nodal, lanczos, global.iterations());
      EXPECT_LE(ratio, nodal * (1.0 + 1e-12)) << k.name;
      EXPECT_LE(nodal, 1.0 + 1e-12) << k.name;
      EXPECT_LE(lanczos, 1.0 + 1e-12) << k.name;
      EXPECT_GE(lanczos, 0.9) << k.name;
      EXPECT_TRUE(global.converged()) << k.name;
    }
  }
}

TEST(StableTimeStep, BisectionOnBlowUpFindsTheCriticalStep) {
  const DynamicsModel model(mesh_spec(MeshFamily::rcp, Rectangle(0, 0, 1, 1), 0.1), kMaterial, 1.0);
  const SplitDofMap dofs = SplitDofMap::continuous(model.mesh);
  InternalForce force(model.mesh, model.matrices);
  const GlobalTimeStep global(force, dofs, model.mass.node_masses(dofs), model.limit);
  const double bound = model.limit.critical(), estimate = global.critical();
  const int steps = 2000;
  double stable = bound, unstable = 3.0 * bound;
  ASSERT_FALSE(free_vibration(model, stable, steps).blown);
  ASSERT_TRUE(free_vibration(model, unstable, steps).blown);
  while (unstable - stable > 1e-6 * bound) {
    const double mid = 0.5 * (stable + unstable);
    (free_vibration(model, mid, steps).blown ? unstable : stable) = mid;
  }
  const double bisected = 0.5 * (stable + unstable), exact = true_critical_step(model);
  std::printf(
      "rcp %d cells: bisected critical step %.6e, eigenvalue %.6e; estimate / bisected: "
      "Lanczos %.4f, cell bound %.4f\n",
      model.mesh.num_cells(), bisected, exact, estimate / bisected, bound / bisected);
  EXPECT_NEAR(bisected, exact, 1e-3 * exact);
  EXPECT_LE(estimate, bisected);
  EXPECT_GE(estimate / bisected, 0.9);
  EXPECT_LE(bound, bisected);

  for (double dt : {global.step(0.9), model.limit.step(0.9)}) {
    const Outcome safe = free_vibration(model, dt, steps);
    std::printf("dt %.4e (safety 0.9): largest energy growth %.3f, balance drift %.2e\n", dt,
                safe.max_growth, safe.balance_drift);
    EXPECT_FALSE(safe.blown);
    EXPECT_LT(safe.max_growth, 10.0);
    EXPECT_LT(safe.balance_drift, 1e-10);
  }
  EXPECT_TRUE(free_vibration(model, 1.1 * exact, steps).blown);
}

}  // namespace
}  // namespace vorodg
