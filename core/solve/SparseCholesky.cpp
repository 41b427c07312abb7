#include "core/solve/SparseCholesky.hpp"

#include <cholmod.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <algorithm>
#include <cmath>
#include <mutex>
#include <vector>

#include "core/solve/GeometricDissection.hpp"
#include "core/util/BlasInfo.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "core/util/Stopwatch.hpp"

namespace vorodg {

namespace {

/// A CHOLMOD view (no copy) of a compressed column-major matrix holding one triangle.
cholmod_sparse view_of(const Eigen::SparseMatrix<double>& m, int stype) {
  cholmod_sparse v{};
  v.nrow = static_cast<size_t>(m.rows());
  v.ncol = static_cast<size_t>(m.cols());
  v.nzmax = static_cast<size_t>(m.nonZeros());
  v.p = const_cast<int*>(m.outerIndexPtr());
  v.i = const_cast<int*>(m.innerIndexPtr());
  v.x = const_cast<double*>(m.valuePtr());
  v.stype = stype;
  v.itype = CHOLMOD_INT;
  v.xtype = CHOLMOD_REAL;
  v.dtype = CHOLMOD_DOUBLE;
  v.sorted = 1;
  v.packed = 1;
  return v;
}

/// Lower-triangle pattern of the node graph: node k = DOFs [b k, b k + b).
struct NodeGraph {
  std::vector<int> col_start, rows;
};

NodeGraph node_graph(const Eigen::SparseMatrix<double>& lower, int b) {
  const int nodes = static_cast<int>(lower.cols()) / b;
  NodeGraph g;
  g.col_start.assign(nodes + 1, 0);
  g.rows.reserve(static_cast<size_t>(lower.nonZeros()) / (b * b) + nodes);
  std::vector<int> seen(nodes, -1);
  const int* p = lower.outerIndexPtr();
  const int* i = lower.innerIndexPtr();
  for (int k = 0; k < nodes; ++k) {
    const size_t begin = g.rows.size();
    for (int j = b * k; j < b * (k + 1); ++j)
      for (int q = p[j]; q < p[j + 1]; ++q) {
        const int m = i[q] / b;
        if (seen[m] != k) seen[m] = k, g.rows.push_back(m);
      }
    std::sort(g.rows.begin() + static_cast<long>(begin), g.rows.end());
    g.col_start[k + 1] = static_cast<int>(g.rows.size());
  }
  return g;
}

/// METIS keeps its random-number state in globals (GKlib's generator, reseeded at each call): two
/// orderings at once on two threads interleave it and give different, equally valid orderings —
/// and different round-off in everything after. Serialized, each ordering is a pure function of
/// its graph again, so study results do not depend on which runs happen to overlap.
std::mutex& metis_lock() {
  static std::mutex lock;
  return lock;
}

/// Expands an ordering of the nodes to the DOFs of each node.
std::vector<int> dof_permutation(const std::vector<int>& node_perm, int b) {
  std::vector<int> perm(node_perm.size() * b);
  for (size_t k = 0; k < node_perm.size(); ++k)
    for (int d = 0; d < b; ++d) perm[b * k + d] = b * node_perm[k] + d;
  return perm;
}

/// A fill-reducing ordering of the node graph (METIS, AMD or the geometric dissection from
/// `points`), expanded to the DOFs of each node.
std::vector<int> node_permutation(const Eigen::SparseMatrix<double>& lower, int b, bool metis,
                                  const Eigen::Matrix2Xd* points, cholmod_common* c) {
  NodeGraph g = node_graph(lower, b);
  const int nodes = static_cast<int>(g.col_start.size()) - 1;
  if (points)
    return dof_permutation(geometric_dissection(symmetric_adjacency(g.col_start, g.rows), *points),
                           b);
  cholmod_sparse view{};
  view.nrow = view.ncol = static_cast<size_t>(nodes);
  view.nzmax = g.rows.size();
  view.p = g.col_start.data();
  view.i = g.rows.data();
  view.stype = -1;
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_PATTERN;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = view.packed = 1;
  std::vector<int> node_perm(nodes);
  std::unique_lock<std::mutex> serial(metis_lock(), std::defer_lock);
  if (metis) serial.lock();
  const int done = metis ? cholmod_metis(&view, nullptr, 0, /*postorder=*/1, node_perm.data(), c)
                         : cholmod_amd(&view, nullptr, 0, node_perm.data(), c);
  if (!done)
    throw NumericalError(std::string(metis ? "METIS" : "AMD") +
                         " could not order the node graph (CHOLMOD status " +
                         std::to_string(c->status) + ")");
  return dof_permutation(node_perm, b);
}

/// The lower triangle of A(p, p) from the lower triangle of A in one counting pass: entry (i, j)
/// goes to (max, min) of (pinv[i], pinv[j]). Its columns come out unsorted (flagged so), which
/// is all the supernodal kernel needs: it scatters each column into its supernode through a
/// map. cholmod_factorize instead transposes twice, to sort them.
cholmod_sparse* permuted_lower(const Eigen::SparseMatrix<double>& lower, const int* perm,
                               cholmod_common* c) {
  const int n = static_cast<int>(lower.cols());
  std::vector<int> pinv(n);
  for (int k = 0; k < n; ++k) pinv[perm[k]] = k;
  const int* p = lower.outerIndexPtr();
  const int* i = lower.innerIndexPtr();
  const double* x = lower.valuePtr();
  cholmod_sparse* out = cholmod_allocate_sparse(n, n, lower.nonZeros(), /*sorted=*/0, /*packed=*/1,
                                                /*stype=*/-1, CHOLMOD_REAL, c);
  if (!out) return nullptr;
  int* op = static_cast<int*>(out->p);
  int* oi = static_cast<int*>(out->i);
  double* ox = static_cast<double*>(out->x);
  std::fill(op, op + n + 1, 0);
  for (int j = 0; j < n; ++j)
    for (int q = p[j]; q < p[j + 1]; ++q) ++op[std::min(pinv[i[q]], pinv[j]) + 1];
  for (int k = 0; k < n; ++k) op[k + 1] += op[k];
  std::vector<int> next(op, op + n);
  for (int j = 0; j < n; ++j)
    for (int q = p[j]; q < p[j + 1]; ++q) {
      const int a = pinv[i[q]], b = pinv[j];
      const int at = next[std::min(a, b)]++;
      oi[at] = std::max(a, b);
      ox[at] = x[q];
    }
  return out;
}

/// Gives the heap's free pages back to the system before the factor, the memory peak of a
/// solve, is allocated. glibc returns only the top of a heap by itself; the holes that the
/// assembly and the element table's released arrays leave in its middle stayed resident (0.2 GB
/// at 1e6 cells, docs/performance.md).
void return_free_memory() {
#ifdef __GLIBC__
  malloc_trim(0);
#endif
}

}  // namespace

struct SparseCholesky::Impl {
  cholmod_common common{};
  cholmod_factor* factor = nullptr;
  Impl() {
    cholmod_start(&common);
    common.print = 0;  // failures are reported by us, in one line, not on stdout
    common.supernodal = CHOLMOD_SUPERNODAL;
  }
  ~Impl() {
    if (factor) cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
  void analyze(const Eigen::SparseMatrix<double>& lower, const FactorizationOptions& options);
  void obtain_analysis(const Eigen::SparseMatrix<double>& lower,
                       const FactorizationOptions& options, FactorizationReport& report);
  void numeric(const Eigen::SparseMatrix<double>& lower, Eigen::SparseMatrix<double>* release);
};

/// The numeric factorization. With `release` (the matrix given up by the caller, `lower`
/// itself) and a permuted supernodal factor, it hands the supernodal kernel the permuted lower
/// triangle built in one pass (cholmod_factorize transposes twice) and frees the caller's
/// matrix before the kernel runs: one copy of the matrix less beside the factor, the memory
/// peak of a solve. The factor is the same to the bit: the kernel places every entry by its
/// row, whatever the order within a column.
void SparseCholesky::Impl::numeric(const Eigen::SparseMatrix<double>& lower,
                                   Eigen::SparseMatrix<double>* release) {
  if (!release || !factor->is_super || factor->ordering == CHOLMOD_NATURAL) {
    cholmod_sparse a = view_of(lower, -1);
    cholmod_factorize(&a, factor, &common);
    if (release) *release = Eigen::SparseMatrix<double>();
    return;
  }
  common.status = CHOLMOD_OK;
  cholmod_sparse* permuted = permuted_lower(lower, static_cast<int*>(factor->Perm), &common);
  *release = Eigen::SparseMatrix<double>();  // CHOLMOD has its own copy now
  return_free_memory();
  double zero[2] = {0.0, 0.0};
  if (permuted) cholmod_super_numeric(permuted, nullptr, zero, factor, &common);
  cholmod_free_sparse(&permuted, &common);
}

/// The analysis shared for this pattern and these settings if there is one, else a new one
/// (kept for the next factorization with the same pattern, if sharing).
void SparseCholesky::Impl::obtain_analysis(const Eigen::SparseMatrix<double>& lower,
                                           const FactorizationOptions& options,
                                           FactorizationReport& report) {
  Stopwatch clock;
  const long settings = static_cast<long>(options.ordering) + 16L * (options.indefinite ? 1 : 0) +
                        256L * options.block_size;
  SymbolicAnalyses* shared = options.shared_analyses;
  if (factor) cholmod_free_factor(&factor, &common);
  if (shared) factor = shared->copy(lower, settings, &common, report.seconds_analyze);
  report.analysis_shared = factor != nullptr;
  if (factor) return;
  analyze(lower, options);
  report.seconds_analyze = clock.seconds();
  if (shared) shared->keep(lower, settings, factor, report.seconds_analyze);
}

void SparseCholesky::Impl::analyze(const Eigen::SparseMatrix<double>& lower,
                                   const FactorizationOptions& options) {
  if (factor) cholmod_free_factor(&factor, &common);
  cholmod_sparse a = view_of(lower, -1);
  const int b = options.block_size;
  const bool has_points = options.node_points && options.node_points->cols() * b == lower.cols();
  const FillOrdering ordering =
      resolve_ordering(options.ordering, lower.cols(),
                       options.reuse_analysis || options.shared_analyses, has_points);
  const bool geometric = ordering == FillOrdering::node_geometric && has_points;
  // Orderings of the node graph pay off only on large graphs; small systems (patch tests, coarse
  // levels) use AMD.
  const bool by_nodes = ordering == FillOrdering::node_metis ||
                        ordering == FillOrdering::node_amd ||
                        ordering == FillOrdering::node_geometric;
  const bool use_nodes = by_nodes && b >= 1 && lower.cols() % b == 0 && lower.cols() >= 4000;
  common.postorder = 1;
  if (use_nodes) {
    std::vector<int> perm = node_permutation(lower, b, ordering != FillOrdering::node_amd,
                                             geometric ? options.node_points : nullptr, &common);
    common.nmethods = 1;
    common.method[0].ordering = CHOLMOD_GIVEN;
    factor = cholmod_analyze_p(&a, perm.data(), nullptr, 0, &common);
  } else {
    common.nmethods = ordering == FillOrdering::cholmod_default ? 0 : 1;
    common.method[0].ordering = CHOLMOD_AMD;
    // CHOLMOD's own choice may try METIS.
    std::unique_lock<std::mutex> serial(metis_lock(), std::defer_lock);
    if (common.nmethods == 0) serial.lock();
    factor = cholmod_analyze(&a, &common);
  }
  if (!factor)
    throw NumericalError("CHOLMOD's symbolic analysis failed (status " +
                         std::to_string(common.status) + ", out of memory?)");
}

FillOrdering resolve_ordering(FillOrdering ordering, long dofs, bool analysis_reused,
                              bool has_points) {
  if (ordering != FillOrdering::automatic) return ordering;
  if (analysis_reused) return FillOrdering::node_metis;
  if (has_points) return FillOrdering::node_geometric;
  return dofs >= kAutoAmdBelowDofs ? FillOrdering::node_metis : FillOrdering::node_amd;
}

SparseCholesky::SparseCholesky() : impl_(std::make_unique<Impl>()) {}
SparseCholesky::~SparseCholesky() = default;

FactorizationReport SparseCholesky::factorize(const Eigen::SparseMatrix<double>& lower,
                                              const FactorizationOptions& options) {
  return factorize(lower, options, nullptr);
}

FactorizationReport SparseCholesky::factorize(Eigen::SparseMatrix<double>&& lower,
                                              const FactorizationOptions& options) {
  Eigen::SparseMatrix<double> owned;
  owned.swap(lower);  // Eigen 3.4's move would copy
  return factorize(owned, options, &owned);
}

FactorizationReport SparseCholesky::factorize(const Eigen::SparseMatrix<double>& lower,
                                              const FactorizationOptions& options,
                                              Eigen::SparseMatrix<double>* release) {
  if (lower.rows() != lower.cols() || !lower.isCompressed())
    throw NumericalError("internal: factorize needs a square compressed matrix");
  FactorizationReport report;
  const ScopedSerialOpenMp serial;  // CHOLMOD's own OpenMP teams only slowed it down
  Stopwatch clock;
  const int mode = options.indefinite ? CHOLMOD_SIMPLICIAL : CHOLMOD_SUPERNODAL;
  const bool reuse = options.reuse_analysis && impl_->factor && impl_->common.supernodal == mode &&
                     impl_->factor->n == static_cast<size_t>(lower.rows());
  if (!reuse) {
    impl_->common.supernodal = mode;
    impl_->common.final_ll = options.indefinite ? 0 : 1;
    impl_->obtain_analysis(lower, options, report);
  } else {
    report.seconds_analyze = 0.0;
  }
  clock.restart();
  impl_->numeric(lower, release);
  report.seconds_factorize = clock.seconds();
  const bool failed =
      impl_->common.status == CHOLMOD_NOT_POSDEF || impl_->factor->minor < impl_->factor->n;
  if (failed && options.indefinite)
    throw NumericalError("the tangent matrix met a zero pivot in its LDL^T factorization");
  if (failed)
    throw NumericalError(
        "the stiffness matrix is not positive definite: the system is singular or indefinite "
        "(rigid-body motions left free, or a material so close to incompressible that the "
        "volumetric stiffness swamps the rest in double precision)");
  if (impl_->common.status < CHOLMOD_OK)
    throw NumericalError("CHOLMOD's factorization failed (status " +
                         std::to_string(impl_->common.status) + ", out of memory?)");
  report.rcond = cholmod_rcond(impl_->factor, &impl_->common);
  report.factor_nonzeros = static_cast<long>(impl_->factor->xsize);
  if (!(report.rcond >= options.min_rcond))
    throw NumericalError(
        "the stiffness matrix is numerically singular (CHOLMOD reciprocal "
        "condition estimate " +
        fmt(report.rcond) + ", below " + fmt(options.min_rcond) + ")");
  return report;
}

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& rhs) const {
  return solve_many(Eigen::MatrixXd(rhs)).col(0);
}

Eigen::MatrixXd SparseCholesky::solve_many(const Eigen::MatrixXd& rhs) const {
  if (!impl_->factor) throw NumericalError("internal: solve before factorize");
  cholmod_dense b{};
  b.nrow = static_cast<size_t>(rhs.rows());
  b.ncol = static_cast<size_t>(rhs.cols());
  b.d = b.nrow;
  b.nzmax = b.nrow * b.ncol;
  b.x = const_cast<double*>(rhs.data());
  b.xtype = CHOLMOD_REAL;
  b.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, impl_->factor, &b, &impl_->common);
  if (!x)
    throw NumericalError("CHOLMOD's solve failed (status " + std::to_string(impl_->common.status) +
                         ")");
  Eigen::MatrixXd result =
      Eigen::Map<const Eigen::MatrixXd>(static_cast<double*>(x->x), rhs.rows(), rhs.cols());
  cholmod_free_dense(&x, &impl_->common);
  if (!result.allFinite()) throw NumericalError("the sparse solve produced non-finite values");
  return result;
}

}  // namespace vorodg
