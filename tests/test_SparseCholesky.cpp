// The sparse Cholesky wrapper: solves small SPD systems given by their lower triangle (against a
// dense solve), serves several right-hand sides from one factor, reports a sensible condition
// estimate, and refuses indefinite, singular and numerically singular matrices with
// NumericalError.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>
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
  EXPECT_THROW(chol3.factorize(lower_of(A), 1e-3), NumericalError);
}

}  // namespace
}  // namespace vorodg
