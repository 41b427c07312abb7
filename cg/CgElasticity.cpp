#include "cg/CgElasticity.hpp"

#include <algorithm>

#include "core/element/LoadIntegrator.hpp"
#include "core/solve/LowerBlockAssembler.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {

CgElasticity::CgElasticity(const ElementTable& table, const ElasticityIntegrator& integrator,
                           const BoundaryValueProblem& problem, int threads,
                           LinearSolverOptions solver)
    : table_(table),
      integrator_(integrator),
      problem_(problem),
      threads_(std::max(threads, 1)),
      solver_options_(solver) {}

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
  const LowerBlockAssembler::ElementNodes cell_nodes = [&](int c, std::vector<int>& nodes) {
    nodes.clear();
    for (int v : mesh.cell_vertices(c)) nodes.push_back(free_node(v));
  };
  LowerBlockAssembler assembler(num_free_dofs() / 2, nc, cell_nodes);
  seconds_["pattern"] = clock.seconds();
  clock.restart();  // each stage's own seconds: a run's stage times add up to its wall time

  Eigen::VectorXd f = Eigen::VectorXd::Zero(num_dofs());
  const DofOf vertex_dof = [&](int c, int k) { return 2 * mesh.cell_vertices(c)[k]; };
  add_body_force(table_, problem_, vertex_dof, f);  // l(v) = (b, v) + <t, v> on traction sides
  add_boundary_tractions(mesh, problem_, vertex_dof, f);
  Eigen::VectorXd lifted = Eigen::VectorXd::Zero(num_dofs());  // K u_D, moved to the right side

  // a(u, v): the cell matrices of a chunk in parallel, then added column range by column range
  // (each thread owns the columns of a node range, so every entry sums in cell order).
  constexpr int kChunk = 16384;
  double matrix_seconds = 0.0;
  for (int first = 0; first < nc; first += kChunk) {
    const int last = std::min(first + kChunk, nc);
    Stopwatch chunk_clock;
    const auto cells = integrator_.cell_matrices(first, last, threads_);
    matrix_seconds += chunk_clock.seconds();
    assembler.add_in_parallel(first, last, threads_, cell_nodes,
                              [&](int c) { return cells.block(c, 2 * mesh.cell_size(c)); });
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
  solver_used_ = resolve_solver(solver_options_.kind, num_free_dofs());
  const Eigen::VectorXd u_free =
      solver_used_ == LinearSolverKind::amg_cg ? solve_by_amg_cg() : solve_by_cholesky();
  const Eigen::VectorXd u = constraints_->expand(u_free);
  displacement_ = Eigen::Map<const Eigen::Matrix2Xd>(u.data(), 2, table_.mesh().num_vertices());
}

Eigen::Matrix2Xd CgElasticity::free_node_points() const {
  const PolygonMesh& mesh = table_.mesh();
  Eigen::Matrix2Xd points(2, num_free_dofs() / 2);
  int placed = 0;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const int x = constraints_->free_index(2 * v), y = constraints_->free_index(2 * v + 1);
    if (x < 0 || y != x + 1 || x % 2 != 0) continue;
    points.col(x / 2) = mesh.vertex(v);
    ++placed;
  }
  return 2 * placed == num_free_dofs() ? points : Eigen::Matrix2Xd();
}

Eigen::VectorXd CgElasticity::solve_by_cholesky() {
  SparseCholesky cholesky;
  const bool geometric = solver_options_.ordering == FillOrdering::node_geometric ||
                         solver_options_.ordering == FillOrdering::automatic;
  const Eigen::Matrix2Xd points = geometric ? free_node_points() : Eigen::Matrix2Xd();
  // The matrix goes to the factorization, which frees it before the factor's values are
  // allocated: one copy of it less at the memory peak of the solve.
  factorization_ =
      cholesky.factorize(std::move(K_), {.ordering = solver_options_.ordering,
                                         .shared_analyses = shared_analyses_,
                                         .node_points = points.cols() ? &points : nullptr});
  seconds_["analysis"] = factorization_.seconds_analyze;
  seconds_["factorization"] = factorization_.seconds_factorize;
  Stopwatch clock;
  Eigen::VectorXd u_free = cholesky.solve(rhs_);
  seconds_["solve"] = clock.seconds();
  return u_free;
}

Eigen::VectorXd CgElasticity::solve_by_amg_cg() {
  const PolygonMesh& mesh = table_.mesh();
  const double tolerance = solver_options_.amg_tolerance > 0.0
                               ? solver_options_.amg_tolerance
                               : amg_tolerance_for(mesh.h_avg(), mesh.domain().scale());
  AmgConjugateGradient amg;
  // Without the rotation mode: nodal coarsening with it costs more here (AmgConjugateGradient).
  amg.setup(K_, Eigen::VectorXd(), {.tolerance = tolerance});
  Eigen::VectorXd u_free = amg.solve(rhs_);
  amg_report_ = amg.report();
  seconds_["amg_setup"] = amg_report_.seconds_setup;
  seconds_["solve"] = amg_report_.seconds_solve;
  return u_free;
}

Eigen::VectorXd CgElasticity::free_rotation_mode() const {
  const PolygonMesh& mesh = table_.mesh();
  const Eigen::Vector2d centre = 0.5 * (mesh.domain().lo() + mesh.domain().hi());
  const double scale = mesh.domain().scale();
  Eigen::VectorXd rotation(num_free_dofs());
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const int f = constraints_->free_index(2 * v);
    if (f < 0) continue;
    const Eigen::Vector2d d = (mesh.vertex(v) - centre) / scale;
    rotation[f] = -d.y();
    rotation[f + 1] = d.x();
  }
  return rotation;
}

Eigen::VectorXd CgElasticity::cell_dofs(int c) const {
  const auto loop = table_.mesh().cell_vertices(c);
  Eigen::VectorXd u(2 * loop.size());
  for (std::size_t k = 0; k < loop.size(); ++k) u.segment<2>(2 * k) = displacement_.col(loop[k]);
  return u;
}

}  // namespace vorodg
