#pragma once
// Iterative solves for what a sparse factor cannot hold: conjugate gradients preconditioned by
// one V-cycle of hypre's BoomerAMG in its systems version for 2D elasticity (the two components
// of a node coarsened apart). The memory is a few copies of the matrix, where a Cholesky factor
// of a 2D elasticity matrix grows like N log N with large constants (docs/solvers.md).
//
// Debian's hypre runs on MPI: its objects live on MPI_COMM_SELF (every process solves its own
// systems), and MPI is initialized on first use if the program has not done so. hypre keeps
// global state (its error flag, the random numbers of its coarsening), so the solves of one
// process run one at a time; results do not depend on which thread runs them.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>

namespace vorodg {

struct AmgCgOptions {
  /// Stop when the preconditioned residual norm sqrt(r' B r), B the V-cycle, has fallen by this
  /// factor from the right-hand side's: it tracks the energy norm of the algebraic error.
  double tolerance = 1e-8;
  int max_iterations = 1000;
  int block_size = 2;  // DOFs per node, numbered consecutively (2k, 2k+1 in 2D)
};

struct AmgCgReport {
  double seconds_setup = 0.0;      // the copy into hypre and the AMG hierarchy
  double seconds_solve = 0.0;      // the CG iterations of the last solve
  int iterations = 0;              // of the last solve
  double relative_residual = 0.0;  // ||b - A x|| / ||b|| (2-norm) after the last solve
  int levels = 0;                  // of the AMG hierarchy
};

class AmgConjugateGradient {
 public:
  /// Whether this vorodg was built with hypre (-DVORODG_HYPRE).
  static bool available();

  AmgConjugateGradient();
  ~AmgConjugateGradient();
  AmgConjugateGradient(const AmgConjugateGradient&) = delete;
  AmgConjugateGradient& operator=(const AmgConjugateGradient&) = delete;

  /// Builds the AMG hierarchy of the symmetric positive definite matrix whose lower triangle is
  /// given; the matrix must outlive the solves (they compute the true residual with it).
  /// `rotation`, the infinitesimal rigid rotation (-y, x) on the DOFs, switches to nodal coarsening
  /// with the rotation in the interpolation (hypre's elasticity setting; measured slower on our
  /// systems, see the .cpp); empty: the unknown-based systems AMG. Throws InputError if hypre is
  /// not available.
  void setup(const Eigen::SparseMatrix<double>& lower, const Eigen::VectorXd& rotation,
             const AmgCgOptions& options = {});
  /// Solves from a zero start. Throws NumericalError if CG does not reach the tolerance within
  /// the iterations or the result is not finite.
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs);

  const AmgCgReport& report() const { return report_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  AmgCgReport report_;
};

}  // namespace vorodg
