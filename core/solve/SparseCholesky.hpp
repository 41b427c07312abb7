#pragma once
// Sparse direct solves: CHOLMOD's supernodal Cholesky (through Eigen's CholmodSupport), which
// runs its dense kernels on the BLAS (OpenBLAS, see blas_description()). A matrix factored once
// serves any number of right-hand sides (the DG iterations back-solve with one factor).
#include <Eigen/SparseCore>
#include <memory>

namespace vorodg {

struct FactorizationReport {
  double rcond = 0.0;              // CHOLMOD's estimate: (min diag L / max diag L)^2
  double seconds_analyze = 0.0;    // ordering and symbolic factorization
  double seconds_factorize = 0.0;  // numeric factorization
  long factor_nonzeros = 0;
};

class SparseCholesky {
 public:
  SparseCholesky();
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  /// Factors the symmetric matrix whose lower triangle is given. Throws NumericalError if it is
  /// not positive definite (a singular system: rigid motions left free by missing Dirichlet
  /// data) or its condition estimate is below `min_rcond`.
  FactorizationReport factorize(const Eigen::SparseMatrix<double>& lower, double min_rcond = 1e-15);
  /// Solves with the current factor. Throws NumericalError on a non-finite result.
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vorodg
