#include "dg/InterfaceOperators.hpp"

#include <algorithm>

#include "core/element/StrainOperator.hpp"

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
  std::vector<int> out;
  for (int s = 0; s < 2; ++s)
    for (int d = 0; d < space_.cell_dof_count(f.cell[s]); ++d)
      out.push_back(space_.cell_offset(f.cell[s]) + d);
  return out;
}

InterfaceOperator InterfaceOperators::jump(const Interface& f, double t) const {
  const int m1 = space_.cell_dof_count(f.cell[0]), m2 = space_.cell_dof_count(f.cell[1]);
  InterfaceOperator J = InterfaceOperator::Zero(2, m1 + m2);
  const int base[2] = {0, m1};
  for (int s = 0; s < 2; ++s) {
    const double sign = s == 0 ? 1.0 : -1.0;
    const int v0 = f.dof_v0[s] - space_.cell_offset(f.cell[s]) + base[s];
    const int v1 = f.dof_v1[s] - space_.cell_offset(f.cell[s]) + base[s];
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

InterfaceOperator InterfaceOperators::mean_traction(const Interface& f) const {
  const int m1 = space_.cell_dof_count(f.cell[0]), m2 = space_.cell_dof_count(f.cell[1]);
  InterfaceOperator T(2, m1 + m2);
  const auto N = traction_map(f.normal);
  T.leftCols(m1) = 0.5 * N * mean_stress_[f.cell[0]];
  T.rightCols(m2) = 0.5 * N * mean_stress_[f.cell[1]];
  return T;
}

InterfaceOperator InterfaceOperators::point_traction(const Interface& f, double t) const {
  const PolygonMesh& mesh = space_.mesh();
  const int m1 = space_.cell_dof_count(f.cell[0]), m2 = space_.cell_dof_count(f.cell[1]);
  InterfaceOperator T(2, m1 + m2);
  const auto N = traction_map(f.normal);
  const Eigen::Matrix3d& D = integrator_.material().D();
  const int v0 = mesh.edge(f.edge).v0;
  for (int s = 0; s < 2; ++s) {
    const int c = f.cell[s];
    const auto loop = mesh.cell_vertices(c);
    const int n = static_cast<int>(loop.size());
    // Cell 1 runs the edge v0 -> v1 (fan of v0), cell 2 runs it v1 -> v0 (fan of v1).
    const int k0 = static_cast<int>(std::find(loop.begin(), loop.end(), v0) - loop.begin());
    const int fan = s == 0 ? k0 : (k0 + n - 1) % n;
    const double along = s == 0 ? t : 1.0 - t;
    double psi[64];
    Eigen::Vector2d grad[64];
    table_.evaluate(c, FanPoint{fan, Eigen::Vector3d(0.0, 1.0 - along, along)}, psi, grad);
    StrainOperator B;
    strain_operator(grad, n, B);
    (s == 0 ? T.leftCols(m1) : T.rightCols(m2)) = 0.5 * N * D * B;
  }
  return T;
}

}  // namespace vorodg
