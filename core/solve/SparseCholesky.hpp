#pragma once
// Sparse direct solves: CHOLMOD's supernodal Cholesky, which runs its dense kernels on the BLAS
// (OpenBLAS, see blas_description()). A matrix factored once serves any number of right-hand
// sides (the DG iterations back-solve with one factor).
//
// The fill-reducing ordering is computed on the graph of the nodes, not of the DOFs: elasticity
// couples the two DOFs of a node with the same neighbours, so METIS on the node graph (a quarter
// of the nonzeros) gives the same fill as METIS on the DOF graph at a fraction of the cost
// (docs/performance.md).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>

#include "core/solve/SymbolicAnalyses.hpp"

namespace vorodg {

/// How the fill-reducing ordering is chosen.
enum class FillOrdering {
  node_metis,  // METIS nested dissection on the node graph (block_size DOFs per node)
  node_amd,    // approximate minimum degree on the node graph: fast, more fill
  /// Nested dissection of the node graph by coordinate bisection (GeometricDissection), from
  /// FactorizationOptions::node_points; node_metis where the caller has none.
  node_geometric,
  amd,              // approximate minimum degree on the DOF graph
  cholmod_default,  // CHOLMOD's own choice: AMD, then METIS if AMD's fill is poor
  /// For a factorization made once (its analysis neither kept for reuse nor shared):
  /// node_geometric where the nodes' points are given, else node_amd below kAutoAmdBelowDofs
  /// unknowns; node_metis otherwise. On one solve the geometric dissection's cheap analysis and
  /// a factor between METIS's and AMD's beat both, and AMD's cheap analysis outweighs METIS's
  /// smaller factor below the size (docs/performance.md, "The ordering"); an analysis that
  /// serves several factorizations, or a factor that serves many solves, wants the smallest
  /// factor.
  automatic,
};

/// Below this many unknowns `automatic` orders a one-off factorization by node AMD (measured to
/// 8.7e5 DOFs; AMD's factor was 13 to 20 % larger, a memory cost that grows with the size).
inline constexpr long kAutoAmdBelowDofs = 1'000'000;

/// The ordering `automatic` stands for (the others stand for themselves).
FillOrdering resolve_ordering(FillOrdering ordering, long dofs, bool analysis_reused,
                              bool has_points = false);

struct FactorizationReport {
  double rcond = 0.0;              // CHOLMOD's estimate: (min diag L / max diag L)^2
  double seconds_analyze = 0.0;    // ordering and symbolic factorization
  double seconds_factorize = 0.0;  // numeric factorization
  long factor_nonzeros = 0;
  /// The analysis was shared (FactorizationOptions::shared_analyses): seconds_analyze is what
  /// making it took, once, for the factorization that kept it.
  bool analysis_shared = false;
};

struct FactorizationOptions {
  FillOrdering ordering = FillOrdering::node_metis;
  int block_size = 2;        // DOFs per node, numbered consecutively (2k, 2k+1 in 2D)
  double min_rcond = 1e-15;  // below this the matrix counts as numerically singular
  /// Simplicial LDL^T (no pivoting) instead of supernodal LL^T: for symmetric matrices that a
  /// softening law can make indefinite (the tangent of cohesive fracture past the peak).
  bool indefinite = false;
  /// Keep the ordering and symbolic factor of the previous call, whose matrix had the same
  /// pattern (Newton iterations, load steps): only the numeric factorization is redone.
  bool reuse_analysis = false;
  /// Analyses shared with other factorizations (of other runs on the same mesh): one kept for
  /// this matrix's pattern is used instead of analyzing again, a new one is kept there.
  SymbolicAnalyses* shared_analyses = nullptr;
  /// The position of each node (block_size DOFs) of the matrix, for FillOrdering::node_geometric.
  const Eigen::Matrix2Xd* node_points = nullptr;
};

class SparseCholesky {
 public:
  SparseCholesky();
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  /// Factors the symmetric matrix whose lower triangle is given. Throws NumericalError if it is
  /// not positive definite (LL^T) or meets a zero pivot (LDL^T) (a singular system: rigid motions
  /// left free by missing Dirichlet data) or its condition estimate is below `options.min_rcond`.
  FactorizationReport factorize(const Eigen::SparseMatrix<double>& lower,
                                const FactorizationOptions& options = {});
  /// The same, for a matrix the caller gives up: it is freed as soon as CHOLMOD holds its own
  /// permuted copy, before the factor's values are allocated, so that the memory peak (the
  /// factor) carries one copy of the matrix instead of two. Same factor to the bit.
  FactorizationReport factorize(Eigen::SparseMatrix<double>&& lower,
                                const FactorizationOptions& options = {});
  /// Solves with the current factor. Throws NumericalError on a non-finite result.
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const;
  /// The same for several right-hand sides at once (one column each): one pass over the factor.
  Eigen::MatrixXd solve_many(const Eigen::MatrixXd& rhs) const;

 private:
  FactorizationReport factorize(const Eigen::SparseMatrix<double>& lower,
                                const FactorizationOptions& options,
                                Eigen::SparseMatrix<double>* release);

  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vorodg
