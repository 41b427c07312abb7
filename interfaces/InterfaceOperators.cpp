#include "interfaces/InterfaceOperators.hpp"

#include <algorithm>

#include "core/element/StrainOperator.hpp"
#include "core/quadrature/TriangleRule.hpp"

namespace vorodg {

InterfaceOperators::InterfaceOperators(const DgSpace& space, const ElasticityIntegrator& integrator,
                                       const ElementTable& table)
    : space_(space), integrator_(integrator), table_(table) {
  const PolygonMesh& mesh = space.mesh();
  mean_stress_.resize(mesh.num_cells());
  for (int c = 0; c < mesh.num_cells(); ++c)
    mean_stress_[c] = integrator.material().D() * integrator.mean_strain_operator(c);
}

std::vector<int> InterfaceOperators::dofs(const Interface& f) const {
  std::vector<int> out = space_.cell_dofs(f.cell[0]);
  const std::vector<int> second = space_.cell_dofs(f.cell[1]);
  out.insert(out.end(), second.begin(), second.end());
  return out;
}

InterfaceOperator InterfaceOperators::jump(const Interface& f, double t) const {
  const int m1 = space_.cell_dof_count(f.cell[0]), m2 = space_.cell_dof_count(f.cell[1]);
  InterfaceOperator J = InterfaceOperator::Zero(2, m1 + m2);
  const int base[2] = {0, m1};
  // Cell 1 runs the edge from v0 (its vertex local_edge) to v1; cell 2 from v1 to v0.
  const PolygonMesh& mesh = space_.mesh();
  for (int s = 0; s < 2; ++s) {
    const double sign = s == 0 ? 1.0 : -1.0;
    const int n = mesh.cell_size(f.cell[s]), first = f.local_edge[s], next = (first + 1) % n;
    const int v0 = base[s] + 2 * (s == 0 ? first : next);
    const int v1 = base[s] + 2 * (s == 0 ? next : first);
    for (int d = 0; d < 2; ++d) {
      J(d, v0 + d) += sign * (1.0 - t);
      J(d, v1 + d) += sign * t;
    }
  }
  return J;
}

Eigen::Matrix<double, 2, 3> InterfaceOperators::traction_map(const Eigen::Vector2d& n) {
  Eigen::Matrix<double, 2, 3> N;
  N << n.x(), 0.0, n.y(), 0.0, n.y(), n.x();
  return N;
}

StressOperator InterfaceOperators::point_stress(int c, int k, double along) const {
  const int n = space_.mesh().cell_size(c);
  double psi[64];
  Eigen::Vector2d grad[64];
  // Barycentric (centroid, v_k, v_k+1) = (0, 1 - along, along): the fan triangle's outer edge.
  table_.evaluate(c, FanPoint{k, Eigen::Vector3d(0.0, 1.0 - along, along)}, psi, grad);
  StrainOperator B;
  strain_operator(grad, n, B);
  return integrator_.material().D() * B;
}

StressOperator InterfaceOperators::fan_stress(int c, int k) const {
  return fan_stresses(c, k)[0];
}

std::vector<StressOperator> InterfaceOperators::fan_stresses(int c, int only) const {
  // B is affine in the gradients: average the gradients per fan triangle, then build one B each.
  const int n = space_.mesh().cell_size(c);
  const int first = only < 0 ? 0 : only, last = only < 0 ? n : only + 1;
  std::vector<Eigen::Vector2d> mean(n * n, Eigen::Vector2d::Zero());
  std::vector<double> areas(n, 0.0);
  for (int q = 0; q < table_.num_points(c); ++q) {
    const int k = table_.fan_point(c, q).fan;
    if (k < first || k >= last) continue;
    const double w = table_.weight(c, q);
    for (int j = 0; j < n; ++j) mean[k * n + j] += w * table_.grad(c, q, j);
    areas[k] += w;
  }
  std::vector<StressOperator> out;
  StrainOperator B;
  for (int k = first; k < last; ++k) {
    if (areas[k] == 0.0) {  // no point in this fan (the virtual element's one point per cell):
      for (int q = 0; q < table_.num_points(c); ++q) {  // its strain is the cell's, constant
        for (int j = 0; j < n; ++j) mean[k * n + j] += table_.weight(c, q) * table_.grad(c, q, j);
        areas[k] += table_.weight(c, q);
      }
    }
    for (int j = 0; j < n; ++j) mean[k * n + j] /= areas[k];
    integrator_.strain_operator_of(c, &mean[k * n], B);
    out.push_back(integrator_.material().D() * B);
  }
  return out;
}

StressOperator InterfaceOperators::edge_stress(int c, int k, double along,
                                               TractionKind kind) const {
  switch (kind) {
    case TractionKind::point: return point_stress(c, k, along);
    case TractionKind::fan: return fan_stress(c, k);
    case TractionKind::mean: break;
  }
  return mean_stress_[c];
}

Eigen::Vector2d InterfaceOperators::edge_normal(int c, int k) const {
  const PolygonMesh& mesh = space_.mesh();
  const auto loop = mesh.cell_vertices(c);
  const int n = static_cast<int>(loop.size());
  const Eigen::Vector2d e = mesh.vertex(loop[(k + 1) % n]) - mesh.vertex(loop[k]);
  return Eigen::Vector2d(e.y(), -e.x()).normalized();  // counter-clockwise loop: outward
}

InterfaceOperator InterfaceOperators::traction(const Interface& f, double t, TractionKind kind,
                                               const Eigen::Vector2d& w) const {
  const int m1 = space_.cell_dof_count(f.cell[0]), m2 = space_.cell_dof_count(f.cell[1]);
  InterfaceOperator T(2, m1 + m2);
  const auto N = traction_map(f.normal);
  // Cell 2 runs the edge the other way: its point t lies a fraction 1 - t along its edge.
  T.leftCols(m1) = w[0] * N * edge_stress(f.cell[0], f.local_edge[0], t, kind);
  T.rightCols(m2) = w[1] * N * edge_stress(f.cell[1], f.local_edge[1], 1.0 - t, kind);
  return T;
}

Eigen::MatrixXd InterfaceOperators::penalty_block(const Interface& f, double eps) const {
  const SegmentRule& rule = gauss2_segment();
  const int m = space_.cell_dof_count(f.cell[0]) + space_.cell_dof_count(f.cell[1]);
  Eigen::MatrixXd block = Eigen::MatrixXd::Zero(m, m);
  for (int g = 0; g < 2; ++g) {
    const double w = rule.weights[g] * f.length;
    const InterfaceOperator J = jump(f, rule.t[g]);
    block += eps * w * J.transpose() * J;
  }
  return block;
}

Eigen::MatrixXd InterfaceOperators::consistency_block(const Interface& f, TractionKind kind,
                                                      const Eigen::Vector2d& w) const {
  const SegmentRule& rule = gauss2_segment();
  const bool constant = kind != TractionKind::point;
  const InterfaceOperator fixed = constant ? traction(f, 0.5, kind, w) : InterfaceOperator();
  const int m = space_.cell_dof_count(f.cell[0]) + space_.cell_dof_count(f.cell[1]);
  Eigen::MatrixXd block = Eigen::MatrixXd::Zero(m, m);
  for (int q = 0; q < 2; ++q)
    block += rule.weights[q] * f.length * jump(f, rule.t[q]).transpose() *
             (constant ? fixed : traction(f, rule.t[q], kind, w));
  return block;
}

Eigen::MatrixXd InterfaceOperators::sipg_block(const Interface& f, double eps, TractionKind kind,
                                               const Eigen::Vector2d& w) const {
  const Eigen::MatrixXd C = consistency_block(f, kind, w);
  return penalty_block(f, eps) - C - C.transpose();
}

}  // namespace vorodg
