#pragma once
// Symbolic analyses of sparse Cholesky factorizations (the fill-reducing ordering and the
// symbolic factor), kept by matrix pattern. The pattern of a stiffness matrix depends on the
// mesh, the space and the Dirichlet sides, not on the material, the penalty or the iteration:
// the runs of a study on one mesh (CG, and every DG variant and k_p) factor with one analysis
// each instead of one per run. A kept analysis is used only for a matrix whose pattern is equal
// entry for entry, so a factorization with it is the same as one that analyzed afresh.
#include <Eigen/SparseCore>
#include <memory>
#include <mutex>
#include <vector>

struct cholmod_factor_struct;
struct cholmod_common_struct;

namespace vorodg {

class SymbolicAnalyses {
 public:
  SymbolicAnalyses();
  ~SymbolicAnalyses();
  SymbolicAnalyses(const SymbolicAnalyses&) = delete;
  SymbolicAnalyses& operator=(const SymbolicAnalyses&) = delete;

  /// A copy, allocated through `common`, of the analysis kept for this lower-triangle pattern
  /// under `settings` (whatever else decides the analysis: ordering, mode, block size), or null;
  /// `seconds` is set to what making the analysis took.
  cholmod_factor_struct* copy(const Eigen::SparseMatrix<double>& lower, long settings,
                              cholmod_common_struct* common, double& seconds) const;
  /// Keeps a copy of `factor`, a symbolic factor (before its numeric factorization), which took
  /// `seconds` to make.
  void keep(const Eigen::SparseMatrix<double>& lower, long settings,
            const cholmod_factor_struct* factor, double seconds);
  int size() const;

 private:
  struct Entry;
  struct Impl;
  std::unique_ptr<Impl> impl_;
  mutable std::mutex mutex_;
};

}  // namespace vorodg
