// CondensedCholesky: solves through the Schur complement of a few varying unknowns agree with a
// dense solve of the whole matrix (symmetric positive definite, and with the varying block made
// indefinite); a matrix that changed outside the varying block is refused; no varying unknowns
// is a plain Cholesky solve.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <random>
#include <vector>

#include "core/solve/CondensedCholesky.hpp"

namespace vorodg {
namespace {

/// The 5-point Laplacian of an m x m grid plus a shift: sparse, symmetric positive definite.
Eigen::SparseMatrix<double> grid_laplacian(int m, double shift) {
  const int n = m * m;
  std::vector<Eigen::Triplet<double>> t;
  for (int y = 0; y < m; ++y)
    for (int x = 0; x < m; ++x) {
      const int i = y * m + x;
      t.emplace_back(i, i, 4.0 + shift);
      if (x + 1 < m) t.emplace_back(i, i + 1, -1.0), t.emplace_back(i + 1, i, -1.0);
      if (y + 1 < m) t.emplace_back(i, i + m, -1.0), t.emplace_back(i + m, i, -1.0);
    }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

/// Adds a symmetric change to the entries among `varying` that the pattern already has.
Eigen::SparseMatrix<double> changed(Eigen::SparseMatrix<double> A, const std::vector<int>& varying,
                                    double size, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-size, size);
  std::vector<char> in(A.cols(), 0);
  for (int g : varying) in[g] = 1;
  for (int j = 0; j < A.cols(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it)
      if (in[it.row()] && in[j] && it.row() >= j) {
        const double d = u(rng);
        it.valueRef() += d;
        if (it.row() != j) A.coeffRef(j, it.row()) += d;
      }
  return A;
}

/// The lower triangle, as the solvers take it.
Eigen::SparseMatrix<double> lower(const Eigen::SparseMatrix<double>& A) {
  return A.triangularView<Eigen::Lower>();
}

Eigen::VectorXd dense_solve(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b) {
  return Eigen::MatrixXd(A).fullPivLu().solve(b);
}

const std::vector<int> kVarying = {3, 17, 18, 19, 40, 41, 77, 150, 151, 152, 153, 200, 333, 399};

TEST(CondensedCholesky, SolvesAsTheWholeMatrixDoes) {
  const Eigen::SparseMatrix<double> A = grid_laplacian(20, 0.1);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), -1.0, 2.0);
  CondensedCholesky solver(kVarying);
  ASSERT_TRUE(solver.factorize(lower(A)));
  EXPECT_EQ(solver.num_varying(), static_cast<int>(kVarying.size()));
  const Eigen::VectorXd x = solver.solve(b), reference = dense_solve(A, b);
  EXPECT_LT((x - reference).norm(), 1e-12 * reference.norm());
}

TEST(CondensedCholesky, SolvesSeveralRightHandSidesAsOneAtATime) {
  const Eigen::SparseMatrix<double> A = changed(grid_laplacian(20, 0.1), kVarying, 8.0, 7u);
  CondensedCholesky solver(kVarying);
  ASSERT_TRUE(solver.factorize(lower(grid_laplacian(20, 0.1))));
  ASSERT_TRUE(solver.factorize(lower(A)));
  Eigen::MatrixXd B(A.rows(), 3);
  B.col(0) = Eigen::VectorXd::Ones(A.rows());
  B.col(1) = Eigen::VectorXd::LinSpaced(A.rows(), -1.0, 1.0);
  B.col(2) = Eigen::VectorXd::Unit(A.rows(), 17);
  const Eigen::MatrixXd X = solver.solve_many(B);
  for (int k = 0; k < 3; ++k) {
    const Eigen::VectorXd x = solver.solve(Eigen::VectorXd(B.col(k)));
    EXPECT_LT((X.col(k) - x).norm(), 1e-13 * x.norm()) << k;
    EXPECT_LT((A * x - B.col(k)).norm(), 1e-10 * B.col(k).norm()) << k;
  }
}

TEST(CondensedCholesky, FollowsTheVaryingBlockIntoIndefiniteness) {
  const Eigen::SparseMatrix<double> A = grid_laplacian(20, 0.1);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(A.rows());
  CondensedCholesky solver(kVarying);
  ASSERT_TRUE(solver.factorize(lower(A)));
  // A softening law's tangent: the varying diagonal pushed far below zero.
  for (unsigned seed : {1u, 2u, 3u}) {
    const Eigen::SparseMatrix<double> B = changed(A, kVarying, 8.0, seed);
    ASSERT_TRUE(solver.factorize(lower(B))) << seed;
    const Eigen::VectorXd x = solver.solve(b), reference = dense_solve(B, b);
    EXPECT_LT((x - reference).norm(), 1e-10 * reference.norm()) << seed;
    EXPECT_LT((B * x - b).norm(), 1e-10 * b.norm()) << seed;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> spectrum(
      Eigen::MatrixXd(changed(A, kVarying, 8.0, 3u)));
  EXPECT_LT(spectrum.eigenvalues()[0], 0.0);  // the last case was indefinite indeed
}

TEST(CondensedCholesky, RefusesAMatrixThatChangedElsewhere) {
  const Eigen::SparseMatrix<double> A = grid_laplacian(12, 0.5);
  CondensedCholesky solver({5, 6, 7});
  ASSERT_TRUE(solver.factorize(lower(A)));
  Eigen::SparseMatrix<double> B = A;
  B.coeffRef(50, 50) += 1e-6;  // a constant unknown's diagonal
  EXPECT_FALSE(solver.factorize(lower(B)));
  Eigen::SparseMatrix<double> C = A;
  C.coeffRef(6, 18) += 0.1, C.coeffRef(18, 6) += 0.1;  // a varying-constant coupling
  EXPECT_FALSE(solver.factorize(lower(C)));
  Eigen::SparseMatrix<double> D = A;
  D.coeffRef(50, 50) += 1e-15;  // round-off of an unchanged sum is allowed
  EXPECT_TRUE(solver.factorize(lower(D)));
}

TEST(CondensedCholesky, WithoutVaryingUnknownsIsAPlainCholeskySolve) {
  const Eigen::SparseMatrix<double> A = grid_laplacian(10, 0.0);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(A.rows(), 1.0, 3.0);
  CondensedCholesky solver({});
  ASSERT_TRUE(solver.factorize(lower(A)));
  const Eigen::VectorXd reference = dense_solve(A, b);
  EXPECT_LT((solver.solve(b) - reference).norm(), 1e-12 * reference.norm());
}

TEST(CondensedCholesky, RefusesVaryingUnknownsOutsideTheMatrix) {
  const Eigen::SparseMatrix<double> A = grid_laplacian(4, 1.0);
  CondensedCholesky solver({2, 16});
  EXPECT_ANY_THROW(solver.factorize(lower(A)));
}

}  // namespace
}  // namespace vorodg
