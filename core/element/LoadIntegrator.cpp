#include "core/element/LoadIntegrator.hpp"

#include <algorithm>

#include "core/quadrature/TriangleRule.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {

void add_body_force(const ElementTable& table, const BoundaryValueProblem& problem,
                    const DofOf& first_dof, Eigen::VectorXd& f) {
  const PolygonMesh& mesh = table.mesh();
  for (int c = 0; c < mesh.num_cells(); ++c) {
    for (int q = 0; q < table.num_points(c); ++q) {
      const Eigen::Vector2d b = problem.body_force(table.point(c, q));
      if (b.isZero()) continue;
      if (!table.has_shape_values())
        throw NumericalError("internal: a body force on an element table built without psi");
      for (int k = 0; k < mesh.cell_size(c); ++k)
        f.segment<2>(first_dof(c, k)) += table.weight(c, q) * table.shape(c, q, k) * b;
    }
  }
}

void add_boundary_tractions(const PolygonMesh& mesh, const BoundaryValueProblem& problem,
                            const DofOf& first_dof, Eigen::VectorXd& f) {
  const SegmentRule& rule = gauss2_segment();
  for (const MeshEdge& e : mesh.edges()) {
    if (!e.on_boundary() || e.side == Side::none) continue;
    if (problem.boundary(e.side) != BoundaryKind::traction) continue;
    const auto loop = mesh.cell_vertices(e.cell0);
    const int k0 = static_cast<int>(std::find(loop.begin(), loop.end(), e.v0) - loop.begin());
    const int k1 = (k0 + 1) % static_cast<int>(loop.size());
    const Point& a = mesh.vertex(e.v0);
    const Eigen::Vector2d tangent = mesh.vertex(e.v1) - a;
    const double length = tangent.norm();
    const Eigen::Vector2d normal(tangent.y() / length, -tangent.x() / length);  // outward
    for (int g = 0; g < 2; ++g) {
      const double t = rule.t[g];
      const Eigen::Vector2d traction = problem.traction(a + t * tangent, normal);
      f.segment<2>(first_dof(e.cell0, k0)) += rule.weights[g] * length * (1 - t) * traction;
      f.segment<2>(first_dof(e.cell0, k1)) += rule.weights[g] * length * t * traction;
    }
  }
}

std::vector<char> dirichlet_vertices(const PolygonMesh& mesh, const BoundaryValueProblem& problem) {
  std::vector<char> fixed(mesh.num_vertices(), 0);
  for (const MeshEdge& e : mesh.edges())
    if (e.on_boundary() && e.side != Side::none &&
        problem.boundary(e.side) == BoundaryKind::dirichlet)
      fixed[e.v0] = fixed[e.v1] = 1;
  return fixed;
}

}  // namespace vorodg
