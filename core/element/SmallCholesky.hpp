#pragma once
// A small dense Cholesky factorization in place, and its two triangular solves: the kernel of the
// weight functions' cell condensation (WeightFunctions), where each cell's interior block is a
// few dozen rows. Row-major, no allocation, and a plain false for a matrix that is not positive
// definite, so a degenerate cell can be reported by its caller.
#include <cmath>

namespace vorodg {

/// Cholesky factor in place of the dense symmetric n x n matrix A (row-major, lower triangle
/// read and overwritten); false if A is not positive definite.
inline bool cholesky_in_place(double* A, int n) {
  for (int j = 0; j < n; ++j) {
    double d = A[j * n + j];
    for (int k = 0; k < j; ++k) d -= A[j * n + k] * A[j * n + k];
    if (!(d > 0.0)) return false;
    d = std::sqrt(d);
    A[j * n + j] = d;
    for (int i = j + 1; i < n; ++i) {
      double v = A[i * n + j];
      for (int k = 0; k < j; ++k) v -= A[i * n + k] * A[j * n + k];
      A[i * n + j] = v / d;
    }
  }
  return true;
}

/// x := L^-1 x, L the factor of cholesky_in_place.
inline void forward_solve(const double* L, int n, double* x) {
  for (int i = 0; i < n; ++i) {
    double v = x[i];
    for (int k = 0; k < i; ++k) v -= L[i * n + k] * x[k];
    x[i] = v / L[i * n + i];
  }
}

/// x := L^-T x.
inline void backward_solve(const double* L, int n, double* x) {
  for (int i = n - 1; i >= 0; --i) {
    double v = x[i];
    for (int k = i + 1; k < n; ++k) v -= L[k * n + i] * x[k];
    x[i] = v / L[i * n + i];
  }
}

}  // namespace vorodg
