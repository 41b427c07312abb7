#include "cg/CgElasticity.hpp"

#include <algorithm>

#include "core/quadrature/TriangleRule.hpp"
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
  if (!problem_.has_dirichlet_side())
    throw InputError("problem '" + problem_.name() +
                         "' prescribes no displacement on any side: the system is singular "
                         "(rigid-body motions are free)");
  // Vertices of Dirichlet edges carry the prescribed displacement (Kronecker delta).
  std::vector<char> fixed(num_dofs(), 0);
  prescribed_ = Eigen::VectorXd::Zero(num_dofs());
  for (const MeshEdge& e : mesh.edges()) {
    if (!e.on_boundary() || e.side == Side::none) continue;
    if (problem_.boundary(e.side) != BoundaryKind::dirichlet) continue;
    for (int v : {e.v0, e.v1}) {
      const Eigen::Vector2d g = problem_.dirichlet_value(mesh.vertex(v));
      fixed[2 * v] = fixed[2 * v + 1] = 1;
      prescribed_.segment<2>(2 * v) = g;
    }
  }
  free_index_.assign(num_dofs(), -1);
  free_.clear();
  for (int d = 0; d < num_dofs(); ++d)
    if (!fixed[d]) {
      free_index_[d] = static_cast<int>(free_.size());
      free_.push_back(d);
    }
  seconds_["setup"] = clock.seconds();
}

void CgElasticity::assemble_system() {
  Stopwatch clock;
  const PolygonMesh& mesh = table_.mesh();
  const int nc = mesh.num_cells();
  // Cell matrices in parallel, each into its own slot; the scatter below runs in cell order, so
  // the assembled matrix does not depend on the thread count.
  std::vector<std::size_t> offset(nc + 1, 0);
  for (int c = 0; c < nc; ++c) offset[c + 1] = offset[c] + 4 * std::size_t(mesh.cell_size(c)) * mesh.cell_size(c);
  std::vector<double> blocks(offset.back());
#pragma omp parallel num_threads(threads_)
  {
    Eigen::MatrixXd Kc;
#pragma omp for schedule(dynamic, 256)
    for (int c = 0; c < nc; ++c) {
      integrator_.cell_matrix(c, Kc);  // a(u, v) on the cell: sum_q w_q B^T D B
      std::copy(Kc.data(), Kc.data() + Kc.size(), blocks.begin() + offset[c]);
    }
  }
  seconds_["cell_matrices"] = clock.seconds();
  clock.restart();

  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(offset.back() / 2 + nc);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(num_dofs());
  add_body_force(f);  // l(v) = (b, v) + <t, v> on traction sides
  add_tractions(f);
  Eigen::VectorXd lifted = Eigen::VectorXd::Zero(num_dofs());  // K u_D, moved to the right side
  for (int c = 0; c < nc; ++c) {
    const auto loop = mesh.cell_vertices(c);
    const int m = 2 * static_cast<int>(loop.size());
    const Eigen::Map<const Eigen::MatrixXd> Kc(blocks.data() + offset[c], m, m);
    for (int j = 0; j < m; ++j) {
      const int gj = 2 * loop[j / 2] + j % 2;
      const int fj = free_index_[gj];
      for (int i = 0; i < m; ++i) {
        const int gi = 2 * loop[i / 2] + i % 2;
        const int fi = free_index_[gi];
        if (fj < 0) {
          lifted[gi] += Kc(i, j) * prescribed_[gj];
        } else if (fi >= fj) {
          triplets.emplace_back(fi, fj, Kc(i, j));
        }
      }
    }
  }
  const int nf = num_free_dofs();
  K_.resize(nf, nf);
  K_.setFromTriplets(triplets.begin(), triplets.end());
  rhs_.resize(nf);
  for (int k = 0; k < nf; ++k) rhs_[k] = f[free_[k]] - lifted[free_[k]];
  seconds_["assembly"] = clock.seconds();
}

void CgElasticity::add_body_force(Eigen::VectorXd& f) const {
  const PolygonMesh& mesh = table_.mesh();
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto loop = mesh.cell_vertices(c);
    for (int q = 0; q < table_.num_points(c); ++q) {
      const Eigen::Vector2d b = problem_.body_force(table_.point(c, q));
      if (b.isZero()) continue;
      for (int k = 0; k < static_cast<int>(loop.size()); ++k)
        f.segment<2>(2 * loop[k]) += table_.weight(c, q) * table_.shape(c, q, k) * b;
    }
  }
}

void CgElasticity::add_tractions(Eigen::VectorXd& f) const {
  // Shape functions are linear along edges: two-point Gauss integrates t psi exactly for linear t.
  const PolygonMesh& mesh = table_.mesh();
  const SegmentRule& rule = gauss2_segment();
  for (const MeshEdge& e : mesh.edges()) {
    if (!e.on_boundary() || e.side == Side::none) continue;
    if (problem_.boundary(e.side) != BoundaryKind::traction) continue;
    const Point& a = mesh.vertex(e.v0);
    const Point& b = mesh.vertex(e.v1);
    const Eigen::Vector2d tangent = b - a;
    const double length = tangent.norm();
    const Eigen::Vector2d normal(tangent.y() / length, -tangent.x() / length);  // outward (ccw)
    for (int g = 0; g < 2; ++g) {
      const double t = rule.t[g];
      const Eigen::Vector2d traction = problem_.traction(a + t * tangent, normal);
      f.segment<2>(2 * e.v0) += rule.weights[g] * length * (1 - t) * traction;
      f.segment<2>(2 * e.v1) += rule.weights[g] * length * t * traction;
    }
  }
}

void CgElasticity::solve() {
  Stopwatch clock;
  SparseCholesky cholesky;
  factorization_ = cholesky.factorize(K_);
  seconds_["analysis"] = factorization_.seconds_analyze;
  seconds_["factorization"] = factorization_.seconds_factorize;
  clock.restart();
  const Eigen::VectorXd u_free = cholesky.solve(rhs_);
  Eigen::VectorXd u = prescribed_;
  for (int k = 0; k < num_free_dofs(); ++k) u[free_[k]] = u_free[k];
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
