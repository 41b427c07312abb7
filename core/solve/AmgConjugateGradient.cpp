#include "core/solve/AmgConjugateGradient.hpp"

#include <malloc.h>

#include <mutex>
#include <numeric>
#include <string>
#include <vector>

#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "core/util/MpiRuntime.hpp"
#include "core/util/Stopwatch.hpp"

#ifdef VORODG_HAVE_HYPRE
#include <HYPRE.h>
#include <HYPRE_parcsr_ls.h>
#include <_hypre_parcsr_ls.h>
#endif

namespace vorodg {

bool AmgConjugateGradient::available() {
#ifdef VORODG_HAVE_HYPRE
  return true;
#else
  return false;
#endif
}

#ifdef VORODG_HAVE_HYPRE
namespace {

/// Debian's hypre links SuperLU_DIST, whose library constructor turns off glibc's use of mmap
/// for large blocks and the trimming of the heap (mallopt M_MMAP_MAX 0, M_TRIM_THRESHOLD -1):
/// memory freed by the program then never goes back to the system. A CG solve at 1e6 cells
/// peaked 3.2 GB higher, because the element table's point values, released before the
/// factorization, stayed resident (docs/solvers.md). This runs after the shared libraries'
/// constructors and restores glibc's defaults, with large blocks (from 32 MiB, the ceiling of
/// glibc's own adaptive threshold) mapped and unmapped on their own.
const bool g_malloc_restored = [] {
  mallopt(M_MMAP_MAX, 65536);
  mallopt(M_TRIM_THRESHOLD, 128 * 1024);
  mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
  return true;
}();

std::mutex g_hypre;  // hypre's global state: one call into it at a time per process

/// The indices 0 .. n-1: every row, as hypre's set and get calls take them.
std::vector<HYPRE_Int> all_rows(int n) {
  std::vector<HYPRE_Int> rows(n);
  std::iota(rows.begin(), rows.end(), 0);
  return rows;
}

/// A hypre vector on MPI_COMM_SELF holding `values` (zeros if empty).
HYPRE_IJVector make_vector(int n, const double* values) {
  HYPRE_IJVector v;
  HYPRE_IJVectorCreate(MPI_COMM_SELF, 0, n - 1, &v);
  HYPRE_IJVectorSetObjectType(v, HYPRE_PARCSR);
  HYPRE_IJVectorInitialize(v);
  const std::vector<HYPRE_Int> rows = all_rows(n);
  const std::vector<double> zeros(values ? 0 : n, 0.0);
  HYPRE_IJVectorSetValues(v, n, rows.data(), values ? values : zeros.data());
  HYPRE_IJVectorAssemble(v);
  return v;
}

HYPRE_ParVector par(HYPRE_IJVector v) {
  HYPRE_ParVector p;
  HYPRE_IJVectorGetObject(v, reinterpret_cast<void**>(&p));
  return p;
}

/// The full symmetric matrix, row by row, from its lower triangle (columns of `lower` are the
/// rows of the upper triangle), handed to hypre in one call.
HYPRE_IJMatrix make_matrix(const Eigen::SparseMatrix<double>& lower) {
  const int n = static_cast<int>(lower.rows());
  std::vector<HYPRE_Int> row_size(n, 0);
  for (int j = 0; j < n; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, j); it; ++it) {
      ++row_size[j];                            // (j, i), i >= j: row j's upper part
      if (it.row() != j) ++row_size[it.row()];  // (i, j): row i's lower part
    }
  std::vector<long> start(n + 1, 0);
  for (int i = 0; i < n; ++i) start[i + 1] = start[i] + row_size[i];
  std::vector<HYPRE_Int> cols(start[n]);
  std::vector<double> values(start[n]);
  std::vector<long> fill(start.begin(), start.end() - 1);
  // Columns in increasing order per row: lower entries (from earlier columns) come first.
  for (int j = 0; j < n; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, j); it; ++it) {
      const int i = static_cast<int>(it.row());
      if (i == j) continue;
      cols[fill[i]] = j, values[fill[i]++] = it.value();
    }
  for (int j = 0; j < n; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, j); it; ++it)
      cols[fill[j]] = static_cast<HYPRE_Int>(it.row()), values[fill[j]++] = it.value();

  HYPRE_IJMatrix A;
  HYPRE_IJMatrixCreate(MPI_COMM_SELF, 0, n - 1, 0, n - 1, &A);
  HYPRE_IJMatrixSetObjectType(A, HYPRE_PARCSR);
  HYPRE_IJMatrixSetRowSizes(A, row_size.data());
  HYPRE_IJMatrixInitialize(A);
  const std::vector<HYPRE_Int> rows = all_rows(n);
  HYPRE_IJMatrixSetValues(A, n, row_size.data(), rows.data(), cols.data(), values.data());
  HYPRE_IJMatrixAssemble(A);
  return A;
}

/// BoomerAMG as one V-cycle per CG iteration, in its systems version: the unknowns of a node
/// are told apart by their component (2k, 2k+1) and coarsened per component ("unknown
/// approach"), with a strength threshold of 0.25 (docs/solvers.md: of the options
/// tried on the rcp beam, the iterations stayed flattest, 18-21 from 4e3 to 1.7e6 DOFs, and
/// grew least as nu -> 1/2).
///
/// With `rotation`, the setting hypre's authors give for elasticity instead: nodal coarsening
/// (a node graph weighted by the row-sum norms of the 2x2 blocks, diagonal as minus their sum)
/// and the rotation added to the interpolation by their GM variant 2 (the translations are
/// interpolated already). Fewer iterations at nu = 0.3 (15-16), but a costlier setup and 2-3
/// times the iterations near incompressibility, so CG elasticity does not use it.
HYPRE_Solver make_preconditioner(int block_size, HYPRE_ParVector* rotation) {
  HYPRE_Solver amg;
  HYPRE_BoomerAMGCreate(&amg);
  HYPRE_BoomerAMGSetPrintLevel(amg, 0);
  HYPRE_BoomerAMGSetMaxIter(amg, 1);  // a preconditioner: one cycle, no own stopping test
  HYPRE_BoomerAMGSetTol(amg, 0.0);
  HYPRE_BoomerAMGSetNumFunctions(amg, block_size);
  HYPRE_BoomerAMGSetAggNumLevels(amg, 0);       // no aggressive coarsening: robustness first
  HYPRE_BoomerAMGSetCycleRelaxType(amg, 8, 3);  // symmetric l1-Gauss-Seidel on the coarsest
  if (!rotation) {
    HYPRE_BoomerAMGSetStrongThreshold(amg, 0.25);
    return amg;
  }
  HYPRE_BoomerAMGSetStrongThreshold(amg, 0.15);  // the best of 0.15-0.5 with the rotation
  HYPRE_BoomerAMGSetNodal(amg, 4);
  HYPRE_BoomerAMGSetNodalDiag(amg, 1);
  HYPRE_BoomerAMGSetInterpVecVariant(amg, 2);
  HYPRE_BoomerAMGSetInterpVecQMax(amg, 4);  // at most 4 extra entries per row
  HYPRE_BoomerAMGSetSmoothInterpVectors(amg, 1);
  HYPRE_BoomerAMGSetInterpRefine(amg, 1);
  HYPRE_BoomerAMGSetInterpVectors(amg, 1, rotation);
  return amg;
}

}  // namespace

struct AmgConjugateGradient::Impl {
  int n = 0;
  HYPRE_IJMatrix A = nullptr;
  HYPRE_IJVector rotation = nullptr;
  HYPRE_ParVector rotation_par = nullptr;
  HYPRE_Solver amg = nullptr, pcg = nullptr;
  const Eigen::SparseMatrix<double>* lower = nullptr;  // the caller's, for the true residual
  AmgCgOptions options;

  void release() {
    if (pcg) HYPRE_ParCSRPCGDestroy(pcg);
    if (amg) HYPRE_BoomerAMGDestroy(amg);
    if (rotation) HYPRE_IJVectorDestroy(rotation);
    if (A) HYPRE_IJMatrixDestroy(A);
    pcg = amg = nullptr, rotation = nullptr, A = nullptr, rotation_par = nullptr;
  }
};

AmgConjugateGradient::AmgConjugateGradient() : impl_(std::make_unique<Impl>()) {}

AmgConjugateGradient::~AmgConjugateGradient() {
  const std::lock_guard lock(g_hypre);
  impl_->release();
}

void AmgConjugateGradient::setup(const Eigen::SparseMatrix<double>& lower,
                                 const Eigen::VectorXd& rotation, const AmgCgOptions& options) {
  mpi_runtime::initialize();
  const std::lock_guard lock(g_hypre);
  Stopwatch clock;
  Impl& s = *impl_;
  s.release();
  s.n = static_cast<int>(lower.rows());
  s.options = options;
  s.lower = &lower;
  s.A = make_matrix(lower);
  if (rotation.size() == s.n) {
    s.rotation = make_vector(s.n, rotation.data());
    s.rotation_par = par(s.rotation);
  }
  s.amg = make_preconditioner(options.block_size, s.rotation ? &s.rotation_par : nullptr);
  HYPRE_ParCSRPCGCreate(MPI_COMM_SELF, &s.pcg);
  HYPRE_PCGSetTol(s.pcg, options.tolerance);
  HYPRE_PCGSetMaxIter(s.pcg, options.max_iterations);
  HYPRE_PCGSetTwoNorm(s.pcg, 0);  // the preconditioned norm: the energy norm's stand-in
  HYPRE_PCGSetRecomputeResidual(s.pcg, 1);
  HYPRE_PCGSetPrecond(s.pcg, reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSolve),
                      reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSetup), s.amg);
  HYPRE_ParCSRMatrix A;
  HYPRE_IJMatrixGetObject(s.A, reinterpret_cast<void**>(&A));
  // The hierarchy is built here, once, with placeholder vectors (setup reads only the matrix).
  HYPRE_IJVector b = make_vector(s.n, nullptr), x = make_vector(s.n, nullptr);
  HYPRE_ParCSRPCGSetup(s.pcg, A, par(b), par(x));
  HYPRE_IJVectorDestroy(b);
  HYPRE_IJVectorDestroy(x);
  report_ = {};
  report_.levels = hypre_ParAMGDataNumLevels(reinterpret_cast<hypre_ParAMGData*>(s.amg));
  report_.seconds_setup = clock.seconds();
}

Eigen::VectorXd AmgConjugateGradient::solve(const Eigen::VectorXd& rhs) {
  Impl& s = *impl_;
  if (!s.pcg) throw std::logic_error("AmgConjugateGradient::solve before setup");
  Eigen::VectorXd u(s.n);
  {
    const std::lock_guard lock(g_hypre);
    Stopwatch clock;
    HYPRE_IJVector b = make_vector(s.n, rhs.data()), x = make_vector(s.n, nullptr);
    HYPRE_ParCSRMatrix A;
    HYPRE_IJMatrixGetObject(s.A, reinterpret_cast<void**>(&A));
    HYPRE_ParCSRPCGSolve(s.pcg, A, par(b), par(x));
    HYPRE_ClearAllErrors();  // non-convergence is judged below, from the residual
    HYPRE_Int iterations = 0;
    HYPRE_PCGGetNumIterations(s.pcg, &iterations);
    const std::vector<HYPRE_Int> rows = all_rows(s.n);
    HYPRE_IJVectorGetValues(x, s.n, rows.data(), u.data());
    HYPRE_IJVectorDestroy(b);
    HYPRE_IJVectorDestroy(x);
    report_.iterations = iterations;
    report_.seconds_solve = clock.seconds();
  }
  const double b_norm = rhs.norm();
  const Eigen::VectorXd r = rhs - s.lower->selfadjointView<Eigen::Lower>() * u;
  report_.relative_residual = b_norm > 0.0 ? r.norm() / b_norm : r.norm();
  if (!u.allFinite())
    throw NumericalError("amg-cg: the solution is not finite after " +
                         std::to_string(report_.iterations) + " iterations");
  if (report_.iterations >= s.options.max_iterations)
    throw NumericalError("amg-cg: no convergence to " + fmt(s.options.tolerance) + " in " +
                         std::to_string(s.options.max_iterations) +
                         " iterations (relative residual " + fmt(report_.relative_residual) + ")");
  return u;
}

#else

struct AmgConjugateGradient::Impl {};
AmgConjugateGradient::AmgConjugateGradient() : impl_(std::make_unique<Impl>()) {}
AmgConjugateGradient::~AmgConjugateGradient() = default;
void AmgConjugateGradient::setup(const Eigen::SparseMatrix<double>&, const Eigen::VectorXd&,
                                 const AmgCgOptions&) {
  throw InputError(
      "solver amg-cg: this vorodg was built without hypre (-DVORODG_HYPRE=OFF); "
      "expected cholmod");
}
Eigen::VectorXd AmgConjugateGradient::solve(const Eigen::VectorXd&) {
  throw std::logic_error("AmgConjugateGradient::solve without hypre");
}

#endif

}  // namespace vorodg
