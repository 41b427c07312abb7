#include "dynamics/MeanGradient.hpp"

#include <cmath>
#include <string>

#include "core/util/Errors.hpp"

namespace vorodg {

MeanGradient::MeanGradient(const PolygonMesh& mesh)
    : offsets_(mesh.offsets()), b_(2 * offsets_.back(), 0.0), area_(mesh.num_cells(), 0.0) {
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto loop = mesh.cell_vertices(c);
    const int n = static_cast<int>(loop.size());
    const Point origin = mesh.vertex(loop[0]);
    double twice_area = 0.0;
    for (int k = 0; k < n; ++k) {
      const Point a = mesh.vertex(loop[k]) - origin, b = mesh.vertex(loop[(k + 1) % n]) - origin;
      twice_area += a.x() * b.y() - b.x() * a.y();
    }
    if (!(std::abs(twice_area) > 0.0))
      throw InputError("mean gradient: cell " + std::to_string(c) + " has no area");
    area_[c] = 0.5 * std::abs(twice_area);
    for (int k = 0; k < n; ++k) {
      const Point a = mesh.vertex(loop[k]) - origin, b = mesh.vertex(loop[(k + 1) % n]) - origin;
      // Edge k (a -> b) gives half of nL = (dy, -dx) to each of its ends, over the area.
      const double nx = (b.y() - a.y()) / twice_area, ny = -(b.x() - a.x()) / twice_area;
      const std::size_t i = 2 * std::size_t(offsets_[c] + k);
      const std::size_t j = 2 * std::size_t(offsets_[c] + (k + 1) % n);
      b_[i] += nx, b_[i + 1] += ny;
      b_[j] += nx, b_[j + 1] += ny;
    }
  }
}

double MeanGradient::divergence(int c, const double* w) const {
  const Eigen::Matrix2d g = gradient(c, w);
  return g(0, 0) + g(1, 1);
}

}  // namespace vorodg
