// The critical step with cohesive springs (CohesiveForces::spring_stiffness, the Lanczos estimate
// of FragmentationRun::estimated_step), on a small rcp mesh (5 x 5 cm, size 1 cm, concrete,
// K0 = 10 E / h), against dense eigensolves of M^-1/2 K M^-1/2:
//   - the springs' matrix stores the faces' energy: with the closure at K0, beta = 1 and no
//     friction every face is the spring K0 I, and u.K_s u / 2 is CohesiveForces' stored energy
//     to 1e-12 at a small random u;
//   - on the map split along every edge, the Lanczos estimate is the dense largest eigenvalue to
//     2e-3 and not below it, and the Gershgorin bound (the cells' plus the springs') is above it;
//   - the split system bounds every crack pattern: the continuous map, and five random sets of
//     cracked edges with their springs on the map split along them, all have a largest
//     eigenvalue at most the split system's (to 1e-12).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "dynamics/CohesiveForces.hpp"
#include "dynamics/GlobalTimeStep.hpp"
#include "support/DynamicsModel.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;

constexpr double kE = 28.3e9, kDensity = 2250.0, kH = 0.01;

struct SpringSystem {
  DynamicsModel model{mesh_spec(MeshFamily::rcp, Rectangle(0, 0, 5 * kH, 5 * kH), kH, 3),
                      IsotropicElasticity(kE, 0.2, PlaneModel::strain), kDensity};
  CohesiveLaw law{CohesiveParameters{3.7e6, 57.0, 1.0, "linear", 10 * kE / kH}};
  ClosureStiffness closure;  // the default: a tenth of K0

  std::vector<char> interior() const {
    std::vector<char> edges(model.mesh.num_edges(), 0);
    for (int e = 0; e < model.mesh.num_edges(); ++e) edges[e] = model.mesh.edge(e).cell1 >= 0;
    return edges;
  }
  /// The map split along `cracked` (every other edge joined).
  SplitDofMap split_along(const std::vector<char>& cracked) const {
    std::vector<char> connected(cracked.size());
    for (std::size_t e = 0; e < cracked.size(); ++e) connected[e] = !cracked[e];
    return SplitDofMap(model.mesh, connected);
  }
  /// Dense K of the cells on `dofs`, column by column through the internal force.
  Eigen::MatrixXd cells_stiffness(const SplitDofMap& dofs) const {
    InternalForce force(model.mesh, model.matrices);
    const int n = dofs.num_dofs();
    Eigen::MatrixXd K(n, n);
    Eigen::VectorXd unit = Eigen::VectorXd::Zero(n), column(n);
    for (int j = 0; j < n; ++j) {
      unit[j] = 1.0;
      force.compute(dofs, unit, column, 1);
      K.col(j) = column;
      unit[j] = 0.0;
    }
    return 0.5 * (K + K.transpose());
  }
  /// Largest eigenvalue of M^-1/2 (K_cells + K_s) M^-1/2 with the springs of `cracked`.
  double largest_eigenvalue(const std::vector<char>& cracked) const {
    const SplitDofMap dofs = split_along(cracked);
    const Eigen::MatrixXd K =
        cells_stiffness(dofs) + Eigen::MatrixXd(CohesiveForces::spring_stiffness(
                                    model.mesh, dofs, law, cracked, 0.75, closure));
    const Eigen::VectorXd m = model.mass.node_masses(dofs);
    Eigen::VectorXd scale(K.rows());
    for (Eigen::Index i = 0; i < K.rows(); ++i) scale[i] = 1.0 / std::sqrt(m[i / 2]);
    const Eigen::MatrixXd A = scale.asDiagonal() * K * scale.asDiagonal();
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A, Eigen::EigenvaluesOnly)
        .eigenvalues()
        .maxCoeff();
  }
};

TEST(SpringTimeStep, TheSpringsMatrixStoresTheFacesEnergy) {
  SpringSystem s;
  s.closure.fraction = 1.0;  // closure = K0: with beta = 1 every face is the spring K0 I
  const std::vector<char> edges = s.interior();
  const SplitDofMap dofs = s.split_along(edges);
  CohesiveForces faces(s.model.mesh, s.law);
  faces.set_closure(s.closure);
  for (int e = 0; e < s.model.mesh.num_edges(); ++e)
    if (edges[e]) faces.add_edge(e);
  faces.bind(dofs);
  // Openings of a hundredth of the law's elastic limit: every point on its elastic branch.
  const double delta0 = s.law.parameters().strength / s.law.parameters().initial_stiffness;
  const Eigen::VectorXd u = random_vector(dofs.num_dofs(), 0.005 * delta0, 17);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(dofs.num_dofs());
  faces.evaluate(u, f);
  const Eigen::SparseMatrix<double> K_s =
      CohesiveForces::spring_stiffness(s.model.mesh, dofs, s.law, edges, 0.0, s.closure);
  const double energy = 0.5 * u.dot(K_s * u);
  EXPECT_NEAR(energy, faces.stored_energy(), 1e-12 * energy);
}

TEST(SpringTimeStep, LanczosFindsTheSplitSystemsEigenvalueBelowTheBound) {
  const SpringSystem s;
  const std::vector<char> edges = s.interior();
  const double dense = s.largest_eigenvalue(edges);
  const SplitDofMap dofs = s.split_along(edges);
  const Eigen::SparseMatrix<double> K_s =
      CohesiveForces::spring_stiffness(s.model.mesh, dofs, s.law, edges, 0.75, s.closure);
  const double bound =
      s.model.limit.max_eigenvalue() +
      CohesiveForces::eigenvalue_bound(s.model.mesh, s.model.mass, s.law, edges, 0.75, s.closure);
  InternalForce force(s.model.mesh, s.model.matrices);
  const GlobalTimeStep lanczos(
      [&](const Eigen::VectorXd& x, Eigen::VectorXd& Kx) {
        force.compute(dofs, x, Kx, 1);
        Kx += K_s * x;
      },
      s.model.mass.node_masses(dofs), bound);
  const double estimate = std::pow(2.0 / lanczos.critical(), 2);
  std::printf(
      "split system: dense %.6e, Lanczos %.6e (%d iterations), bound %.6e: steps %.4f "
      "and %.4f of the true one\n",
      dense, estimate, lanczos.iterations(), bound, std::sqrt(dense / estimate),
      std::sqrt(dense / bound));
  EXPECT_TRUE(lanczos.converged());
  EXPECT_GE(estimate, dense * (1.0 - 1e-12));
  EXPECT_LE(estimate, dense * (1.0 + 2e-3));
  EXPECT_GE(bound, dense);
}

TEST(SpringTimeStep, TheSplitSystemBoundsEveryCrackPattern) {
  const SpringSystem s;
  const std::vector<char> every = s.interior();
  const double split = s.largest_eigenvalue(every);
  const std::vector<char> none(every.size(), 0);
  EXPECT_LE(s.largest_eigenvalue(none), split * (1.0 + 1e-12));
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const Eigen::VectorXd draw = random_vector(static_cast<int>(every.size()), 1.0, seed);
    std::vector<char> cracked(every.size(), 0);
    for (std::size_t e = 0; e < every.size(); ++e) cracked[e] = every[e] && draw[e] > 0.0;
    const double pattern = s.largest_eigenvalue(cracked);
    EXPECT_LE(pattern, split * (1.0 + 1e-12)) << "seed " << seed;
    std::printf("cracked set %d: largest eigenvalue %.4f of the split system's\n",
                static_cast<int>(seed), pattern / split);
  }
}

}  // namespace
}  // namespace vorodg
