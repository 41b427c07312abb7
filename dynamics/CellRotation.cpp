#include "dynamics/CellRotation.hpp"

#include <algorithm>
#include <cmath>

namespace vorodg {

double cell_rotation(const PolygonMesh& mesh, const SplitDofMap& dofs, const Eigen::VectorXd& u,
                     int c) {
  const auto vertices = mesh.cell_vertices(c);
  const int n = static_cast<int>(vertices.size());
  double twice_area = 0.0, circulation = 0.0;
  for (int k = 0; k < n; ++k) {
    const int l = (k + 1) % n;
    const Point& a = mesh.vertex(vertices[k]);
    const Point& b = mesh.vertex(vertices[l]);
    const Eigen::Vector2d ua = u.segment<2>(2 * dofs.node(c, k));
    const Eigen::Vector2d ub = u.segment<2>(2 * dofs.node(c, l));
    twice_area += a.x() * b.y() - b.x() * a.y();
    circulation +=
        0.5 * ((ua.y() + ub.y()) * (b.y() - a.y()) + (ua.x() + ub.x()) * (b.x() - a.x()));
  }
  return circulation / twice_area;
}

double max_cell_rotation(const PolygonMesh& mesh, const SplitDofMap& dofs,
                         const Eigen::VectorXd& u) {
  double largest = 0.0;
  for (int c = 0; c < mesh.num_cells(); ++c)
    largest = std::max(largest, std::abs(cell_rotation(mesh, dofs, u, c)));
  return largest;
}

}  // namespace vorodg
