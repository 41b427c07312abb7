// The sparse Cholesky wrapper: solves small SPD systems given by their lower triangle (against a
// dense solve), serves several right-hand sides from one factor, reports a sensible condition
// estimate, refuses indefinite, singular and numerically singular matrices with NumericalError,
// and runs on the calling thread alone (CHOLMOD opens no OpenMP team of its own).
#include <gtest/gtest.h>

#include <omp.h>
#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <cmath>
#include <filesystem>
#include <iterator>
#include <thread>
#include <vector>

#include "core/solve/SparseCholesky.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

using SpMat = Eigen::SparseMatrix<double>;

SpMat lower_of(const Eigen::MatrixXd& A) {
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j < A.cols(); ++j)
    for (int i = j; i < A.rows(); ++i)
      if (A(i, j) != 0.0) t.emplace_back(i, j, A(i, j));
  SpMat L(A.rows(), A.cols());
  L.setFromTriplets(t.begin(), t.end());
  return L;
}

// A small SPD matrix with a 2D-Laplacian-like pattern plus a random symmetric perturbation.
Eigen::MatrixXd spd_matrix(int n) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    A(i, i) = 4.0 + 0.1 * i;
    if (i + 1 < n) A(i, i + 1) = A(i + 1, i) = -1.0;
    if (i + 4 < n) A(i, i + 4) = A(i + 4, i) = -1.0 + 0.01 * i;
  }
  return A;
}

/// The lower triangle of a 2-DOF-per-node n x n grid operator, SPD, coupled within each node.
SpMat grid_lower(int n) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int a = i * n + j;
      for (int d = 0; d < 2; ++d) t.emplace_back(2 * a + d, 2 * a + d, 4.5 + 0.01 * d);
      t.emplace_back(2 * a + 1, 2 * a, 0.3);
      if (i + 1 < n)
        for (int d = 0; d < 2; ++d) t.emplace_back(2 * (a + n) + d, 2 * a + d, -1.0);
      if (j + 1 < n)
        for (int d = 0; d < 2; ++d) t.emplace_back(2 * (a + 1) + d, 2 * a + d, -1.0);
    }
  SpMat lower(2 * n * n, 2 * n * n);
  lower.setFromTriplets(t.begin(), t.end());
  return lower;
}

/// The threads of this process now.
long process_threads() {
  return std::distance(std::filesystem::directory_iterator("/proc/self/task"),
                       std::filesystem::directory_iterator{});
}

TEST(SparseCholesky, SolvesSmallSpdSystem) {
  const int n = 24;
  const Eigen::MatrixXd A = spd_matrix(n);
  ASSERT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A).eigenvalues().minCoeff(), 0.0);
  SparseCholesky chol;
  const FactorizationReport report = chol.factorize(lower_of(A));
  EXPECT_GT(report.rcond, 0.0);
  EXPECT_LE(report.rcond, 1.0);
  EXPECT_GT(report.factor_nonzeros, 0);
  EXPECT_GE(report.seconds_analyze, 0.0);
  EXPECT_GE(report.seconds_factorize, 0.0);
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) b[i] = std::sin(1.0 + i);
  const Eigen::VectorXd x = chol.solve(b);
  const Eigen::VectorXd x_ref = A.ldlt().solve(b);
  EXPECT_LT((x - x_ref).norm(), 1e-12 * x_ref.norm());
  EXPECT_LT((A * x - b).norm(), 1e-12 * b.norm());
}

TEST(SparseCholesky, OneFactorManyRightHandSides) {
  const int n = 17;
  const Eigen::MatrixXd A = spd_matrix(n);
  SparseCholesky chol;
  chol.factorize(lower_of(A));
  for (int k = 0; k < 4; ++k) {
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0 + k, 2.0 * k + 0.5);
    const Eigen::VectorXd x = chol.solve(b);
    EXPECT_LT((A * x - b).norm(), 1e-12 * b.norm()) << "rhs " << k;
  }
}

TEST(SparseCholesky, RefactorizesAnotherMatrix) {
  SparseCholesky chol;
  chol.factorize(lower_of(spd_matrix(10)));
  const Eigen::MatrixXd B = 2.0 * spd_matrix(12);
  chol.factorize(lower_of(B));
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(12);
  EXPECT_LT((B * chol.solve(b) - b).norm(), 1e-12 * b.norm());
}

TEST(SparseCholesky, ConditionEstimateOfDiagonalMatrix) {
  // rcond = (min diag L / max diag L)^2 = min / max eigenvalue for a diagonal matrix.
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(3, 3);
  A.diagonal() << 4.0, 1.0, 0.25;
  SparseCholesky chol;
  const FactorizationReport report = chol.factorize(lower_of(A));
  EXPECT_NEAR(report.rcond, 0.25 / 4.0, 1e-14);
  EXPECT_LT((chol.solve(Eigen::Vector3d(4, 1, 0.25)) - Eigen::Vector3d::Ones()).norm(), 1e-15);
}

TEST(SparseCholesky, ThrowsForIndefiniteMatrix) {
  Eigen::MatrixXd A(3, 3);
  A << 2, 1, 0,  //
      1, -3, 1,  //
      0, 1, 2;
  SparseCholesky chol;
  EXPECT_THROW(chol.factorize(lower_of(A)), NumericalError);
  Eigen::MatrixXd N = -Eigen::MatrixXd::Identity(4, 4);  // negative definite
  SparseCholesky chol2;
  EXPECT_THROW(chol2.factorize(lower_of(N)), NumericalError);
}

TEST(SparseCholesky, ThrowsForSingularMatrix) {
  // Exactly singular: rank one.
  Eigen::MatrixXd A(2, 2);
  A << 1, 1, 1, 1;
  SparseCholesky chol;
  EXPECT_THROW(chol.factorize(lower_of(A)), NumericalError);
  // A free-free 1D stiffness (constants in its null space), like a body without supports.
  const int n = 8;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
  for (int e = 0; e + 1 < n; ++e) {
    K(e, e) += 1;
    K(e + 1, e + 1) += 1;
    K(e, e + 1) -= 1;
    K(e + 1, e) -= 1;
  }
  SparseCholesky chol2;
  EXPECT_THROW(chol2.factorize(lower_of(K)), NumericalError);
  // A zero column.
  Eigen::MatrixXd Z = Eigen::MatrixXd::Identity(3, 3);
  Z(1, 1) = 0.0;
  SparseCholesky chol3;
  EXPECT_THROW(chol3.factorize(lower_of(Z)), NumericalError);
}

TEST(SparseCholesky, ThrowsBelowTheConditionThreshold) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(3, 3);
  A(2, 2) = 1e-20;  // positive definite but numerically singular
  SparseCholesky chol;
  EXPECT_THROW(chol.factorize(lower_of(A)), NumericalError);
  A(2, 2) = 1e-6;
  SparseCholesky chol2;
  EXPECT_NO_THROW(chol2.factorize(lower_of(A)));
  SparseCholesky chol3;
  EXPECT_THROW(chol3.factorize(lower_of(A), {.min_rcond = 1e-3}), NumericalError);
}

// A vector Laplacian on an m x m grid with two coupled DOFs per node (numbered 2k, 2k+1), large
// enough (8450 DOFs) that the node-graph METIS ordering is used.
SpMat block_laplacian_lower(int m) {
  std::vector<Eigen::Triplet<double>> t;
  auto node = [m](int i, int j) { return i * m + j; };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j) {
      const int k = node(i, j);
      for (int d = 0; d < 2; ++d) t.emplace_back(2 * k + d, 2 * k + d, 8.0 + 0.001 * k);
      t.emplace_back(2 * k + 1, 2 * k, 0.5);  // the two DOFs of a node couple
      const int nb[2] = {j + 1 < m ? node(i, j + 1) : -1, i + 1 < m ? node(i + 1, j) : -1};
      for (int n : nb)
        if (n >= 0)
          for (int a = 0; a < 2; ++a)
            for (int b = 0; b < 2; ++b) t.emplace_back(2 * n + a, 2 * k + b, a == b ? -1.0 : -0.2);
    }
  SpMat L(2 * m * m, 2 * m * m);
  L.setFromTriplets(t.begin(), t.end());
  return L;
}

TEST(SparseCholesky, NodeGraphOrderingSolvesLikeAmdWithLessFill) {
  const SpMat L = block_laplacian_lower(65);
  const SpMat full = SpMat(L.selfadjointView<Eigen::Lower>());
  Eigen::VectorXd b(L.rows());
  for (int i = 0; i < b.size(); ++i) b[i] = std::cos(0.37 * i);
  SparseCholesky by_nodes, by_amd;
  const FactorizationReport r_nodes = by_nodes.factorize(L, {.ordering = FillOrdering::node_metis});
  const FactorizationReport r_amd = by_amd.factorize(L, {.ordering = FillOrdering::amd});
  const Eigen::VectorXd x_nodes = by_nodes.solve(b), x_amd = by_amd.solve(b);
  EXPECT_LT((full * x_nodes - b).norm(), 1e-12 * b.norm());
  EXPECT_LT((x_nodes - x_amd).norm(), 1e-12 * x_amd.norm());
  // Nested dissection beats minimum degree on a 2D grid; allow 10% either way of noise-free fill.
  EXPECT_LT(r_nodes.factor_nonzeros, 1.1 * r_amd.factor_nonzeros);
  SparseCholesky by_node_amd;
  by_node_amd.factorize(L, {.ordering = FillOrdering::node_amd});
  EXPECT_LT((by_node_amd.solve(b) - x_amd).norm(), 1e-12 * x_amd.norm());
  // The estimate reads the diagonal of L, which depends on the ordering: same order only.
  EXPECT_GT(r_nodes.rcond, 0.5 * r_amd.rcond);
  EXPECT_LT(r_nodes.rcond, 2.0 * r_amd.rcond);
}

// `auto`: for a factorization made once, the geometric dissection where the nodes' points are
// given, else node AMD below the size; node METIS when the analysis is kept for reuse or shared,
// or the system is large; the explicit orderings stand for themselves.
TEST(SparseCholesky, AutoOrdersALoneFactorizationByNodeAmdAndAKeptOneByMetis) {
  const SpMat L = block_laplacian_lower(65);
  const auto nonzeros = [&](FactorizationOptions options) {
    SparseCholesky chol;
    return chol.factorize(L, options).factor_nonzeros;
  };
  const long metis = nonzeros({.ordering = FillOrdering::node_metis});
  const long amd = nonzeros({.ordering = FillOrdering::node_amd});
  ASSERT_NE(metis, amd);  // the case tells the two apart
  EXPECT_EQ(nonzeros({.ordering = FillOrdering::automatic}), amd);
  EXPECT_EQ(nonzeros({.ordering = FillOrdering::automatic, .reuse_analysis = true}), metis);
  SymbolicAnalyses shared;
  EXPECT_EQ(nonzeros({.ordering = FillOrdering::automatic, .shared_analyses = &shared}), metis);
  EXPECT_EQ(resolve_ordering(FillOrdering::automatic, kAutoAmdBelowDofs - 1, false),
            FillOrdering::node_amd);
  EXPECT_EQ(resolve_ordering(FillOrdering::automatic, kAutoAmdBelowDofs, false),
            FillOrdering::node_metis);
  EXPECT_EQ(resolve_ordering(FillOrdering::automatic, 10 * kAutoAmdBelowDofs, false, true),
            FillOrdering::node_geometric);
  EXPECT_EQ(resolve_ordering(FillOrdering::automatic, 10, true, true), FillOrdering::node_metis);
  for (FillOrdering o : {FillOrdering::node_metis, FillOrdering::node_amd, FillOrdering::amd,
                         FillOrdering::node_geometric, FillOrdering::cholmod_default})
    EXPECT_EQ(resolve_ordering(o, 10, false), o);
}

TEST(SparseCholesky, OddSizeFallsBackToAmd) {
  SpMat L = block_laplacian_lower(65);
  L.conservativeResize(L.rows() - 1, L.cols() - 1);  // a node with one DOF: no node graph
  L.makeCompressed();
  SparseCholesky chol;
  const FactorizationReport r = chol.factorize(L);
  EXPECT_GT(r.factor_nonzeros, 0);
  Eigen::VectorXd b = Eigen::VectorXd::Ones(L.rows());
  const SpMat full = SpMat(L.selfadjointView<Eigen::Lower>());
  EXPECT_LT((full * chol.solve(b) - b).norm(), 1e-12 * b.norm());
}

}  // namespace
}  // namespace vorodg

namespace vorodg {
namespace {

// A matrix given up to the factorization is freed early, and factors to the same bits.
TEST(SparseCholesky, AMatrixGivenUpFactorsToTheSameBits) {
  for (int n : {12, 60}) {  // 288 DOFs (AMD on the DOFs), 7200 DOFs (METIS on the nodes)
    const SpMat lower = grid_lower(n);
    SpMat given = lower;
    SparseCholesky kept, consumed;
    const FactorizationReport a = kept.factorize(lower);
    const FactorizationReport b = consumed.factorize(std::move(given));
    EXPECT_EQ(given.nonZeros(), 0);
    EXPECT_EQ(a.factor_nonzeros, b.factor_nonzeros);
    EXPECT_EQ(a.rcond, b.rcond);
    const Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(lower.rows(), 1.0, -2.0);
    const Eigen::VectorXd x = kept.solve(rhs), y = consumed.solve(rhs);
    for (Eigen::Index i = 0; i < rhs.size(); ++i)
      ASSERT_EQ(x[i], y[i]) << "n " << n << " entry " << i;
  }
}

// CHOLMOD's supernodal kernel opens OpenMP teams of 4 around its scatter loops whatever the
// thread settings; they made a one-thread factorization 2.6x slower. The factorization runs
// them on the calling thread alone. A fresh thread has no OpenMP workers, so any team it
// opened would show as new threads of the process.
TEST(SparseCholesky, OpensNoOpenMpTeamOfItsOwn) {
  const SpMat lower = grid_lower(150);  // 45,000 DOFs: supernodes large enough for the teams
  long before = 0, after = 0;
  std::thread fresh([&] {
    before = process_threads();
    SparseCholesky chol;
    chol.factorize(lower);
    after = process_threads();
  });
  fresh.join();
  EXPECT_EQ(after, before);
  int team = 0;
#pragma omp parallel num_threads(2)
  {
#pragma omp single
    team = omp_get_num_threads();
  }
  EXPECT_EQ(team, 2) << "the calling thread's own regions are left as they were";
}

}  // namespace
}  // namespace vorodg
