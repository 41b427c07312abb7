#include "cg/CgElasticity.hpp"

#include <algorithm>

#include "core/element/LoadIntegrator.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {

CgElasticity::CgElasticity(const ElementTable& table, const ElasticityIntegrator& integrator,
                           const BoundaryValueProblem& problem, int threads)
    : table_(table), integrator_(integrator), problem_(problem), threads_(std::max(threads, 1)) {}

void CgElasticity::run() {
  setup_system();
  assemble_system();
  solve();
}

void CgElasticity::setup_system() {
  Stopwatch clock;
  const PolygonMesh& mesh = table_.mesh();
  constraints_.emplace(mesh, problem_, [&](int c, int k) { return 2 * mesh.cell_vertices(c)[k]; },
                       num_dofs());
  seconds_["setup"] = clock.seconds();
}

void CgElasticity::assemble_system() {
  Stopwatch clock;
  const PolygonMesh& mesh = table_.mesh();
  const int nc = mesh.num_cells();
  // a(u, v) per cell, in parallel; the scatter below runs in cell order (thread-independent).
  const auto cells = integrator_.all_cell_matrices(threads_);
  seconds_["cell_matrices"] = clock.seconds();
  clock.restart();

  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(cells.data.size() / 2 + nc);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(num_dofs());
  const DofOf vertex_dof = [&](int c, int k) { return 2 * mesh.cell_vertices(c)[k]; };
  add_body_force(table_, problem_, vertex_dof, f);  // l(v) = (b, v) + <t, v> on traction sides
  add_boundary_tractions(mesh, problem_, vertex_dof, f);
  Eigen::VectorXd lifted = Eigen::VectorXd::Zero(num_dofs());  // K u_D, moved to the right side
  for (int c = 0; c < nc; ++c) {
    const auto loop = mesh.cell_vertices(c);
    const int m = 2 * static_cast<int>(loop.size());
    const auto Kc = cells.block(c, m);
    for (int j = 0; j < m; ++j) {
      const int gj = 2 * loop[j / 2] + j % 2;
      const int fj = constraints_->free_index(gj);
      for (int i = 0; i < m; ++i) {
        const int gi = 2 * loop[i / 2] + i % 2;
        const int fi = constraints_->free_index(gi);
        if (fj < 0) {
          lifted[gi] += Kc(i, j) * constraints_->prescribed()[gj];
        } else if (fi >= fj) {
          triplets.emplace_back(fi, fj, Kc(i, j));
        }
      }
    }
  }
  const int nf = num_free_dofs();
  K_.resize(nf, nf);
  K_.setFromTriplets(triplets.begin(), triplets.end());
  rhs_ = constraints_->restrict(f - lifted);
  seconds_["assembly"] = clock.seconds();
}

void CgElasticity::solve() {
  Stopwatch clock;
  SparseCholesky cholesky;
  factorization_ = cholesky.factorize(K_);
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
