#include "cg/CgElasticity.hpp"

#include <algorithm>

#include <omp.h>

#include "core/element/LoadIntegrator.hpp"
#include "core/solve/LowerBlockAssembler.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {

CgElasticity::CgElasticity(const ElementTable& table, const ElasticityIntegrator& integrator,
                           const BoundaryValueProblem& problem, int threads, FillOrdering ordering)
    : table_(table),
      integrator_(integrator),
      problem_(problem),
      threads_(std::max(threads, 1)),
      ordering_(ordering) {}

void CgElasticity::run() {
  setup_system();
  assemble_system();
  solve();
}

void CgElasticity::setup_system() {
  Stopwatch clock;
  const PolygonMesh& mesh = table_.mesh();
  constraints_.emplace(
      mesh, problem_, [&](int c, int k) { return 2 * mesh.cell_vertices(c)[k]; }, num_dofs());
  seconds_["setup"] = clock.seconds();
}

void CgElasticity::assemble_system() {
  Stopwatch clock;
  const PolygonMesh& mesh = table_.mesh();
  const int nc = mesh.num_cells();
  // Free DOFs come in node pairs (both components of a vertex are prescribed or free).
  const auto free_node = [&](int v) {
    const int f = constraints_->free_index(2 * v);
    return f < 0 ? -1 : f / 2;
  };
  LowerBlockAssembler assembler(num_free_dofs() / 2, nc, [&](int c, std::vector<int>& nodes) {
    nodes.clear();
    for (int v : mesh.cell_vertices(c)) nodes.push_back(free_node(v));
  });
  seconds_["pattern"] = clock.seconds();

  Eigen::VectorXd f = Eigen::VectorXd::Zero(num_dofs());
  const DofOf vertex_dof = [&](int c, int k) { return 2 * mesh.cell_vertices(c)[k]; };
  add_body_force(table_, problem_, vertex_dof, f);  // l(v) = (b, v) + <t, v> on traction sides
  add_boundary_tractions(mesh, problem_, vertex_dof, f);
  Eigen::VectorXd lifted = Eigen::VectorXd::Zero(num_dofs());  // K u_D, moved to the right side

  // a(u, v): the cell matrices of a chunk in parallel, then added column range by column range
  // (each thread owns the columns of a node range, so every entry sums in cell order).
  constexpr int kChunk = 16384;
  const int nodes = num_free_dofs() / 2;
  double matrix_seconds = 0.0;
  std::vector<int> cell_nodes;
  for (int first = 0; first < nc; first += kChunk) {
    const int last = std::min(first + kChunk, nc);
    Stopwatch chunk_clock;
    const auto cells = integrator_.cell_matrices(first, last, threads_);
    matrix_seconds += chunk_clock.seconds();
#pragma omp parallel num_threads(threads_)
    {
      const int t = omp_get_thread_num(), nt = omp_get_num_threads();
      const int node_begin = static_cast<int>(static_cast<long>(nodes) * t / nt);
      const int node_end = static_cast<int>(static_cast<long>(nodes) * (t + 1) / nt);
      std::vector<int> local_nodes;
      for (int c = first; c < last; ++c) {
        local_nodes.clear();
        for (int v : mesh.cell_vertices(c)) local_nodes.push_back(free_node(v));
        assembler.add(local_nodes, cells.block(c, 2 * mesh.cell_size(c)), node_begin, node_end);
      }
    }
    for (int c = first; c < last; ++c)
      add_lifting(c, cells.block(c, 2 * mesh.cell_size(c)), lifted);
  }
  K_ = assembler.release();
  rhs_ = constraints_->restrict(f - lifted);
  seconds_["cell_matrices"] = matrix_seconds;
  seconds_["assembly"] = clock.seconds() - matrix_seconds;
}

/// K_c u_D of a cell with prescribed vertices, added to `lifted` (it moves to the right side).
void CgElasticity::add_lifting(int c, const Eigen::Ref<const Eigen::MatrixXd>& Kc,
                               Eigen::VectorXd& lifted) const {
  const auto loop = table_.mesh().cell_vertices(c);
  const int m = 2 * static_cast<int>(loop.size());
  for (int j = 0; j < m; ++j) {
    const int gj = 2 * loop[j / 2] + j % 2;
    if (constraints_->free_index(gj) >= 0) continue;
    const double uD = constraints_->prescribed()[gj];
    for (int i = 0; i < m; ++i) lifted[2 * loop[i / 2] + i % 2] += Kc(i, j) * uD;
  }
}

void CgElasticity::solve() {
  Stopwatch clock;
  SparseCholesky cholesky;
  factorization_ = cholesky.factorize(K_, {.ordering = ordering_});
  seconds_["analysis"] = factorization_.seconds_analyze;
  seconds_["factorization"] = factorization_.seconds_factorize;
  clock.restart();
  const Eigen::VectorXd u_free = cholesky.solve(rhs_);
  const Eigen::VectorXd u = constraints_->expand(u_free);
  displacement_ = Eigen::Map<const Eigen::Matrix2Xd>(u.data(), 2, table_.mesh().num_vertices());
  seconds_["solve"] = clock.seconds();
}

Eigen::VectorXd CgElasticity::cell_dofs(int c) const {
  const auto loop = table_.mesh().cell_vertices(c);
  Eigen::VectorXd u(2 * loop.size());
  for (std::size_t k = 0; k < loop.size(); ++k) u.segment<2>(2 * k) = displacement_.col(loop[k]);
  return u;
}

}  // namespace vorodg
