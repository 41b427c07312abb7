#include "dynamics/CorotationalFrames.hpp"

#include <algorithm>
#include <cmath>

namespace vorodg {

CorotationalFrames::CorotationalFrames(const PolygonMesh& mesh)
    : gradient_(mesh), offsets_(mesh.offsets()), p_(2 * offsets_.back()) {
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto loop = mesh.cell_vertices(c);
    const Point origin = mesh.vertex(loop[0]);
    for (int k = 0; k < static_cast<int>(loop.size()); ++k) {
      const Point a = mesh.vertex(loop[k]) - origin;
      const std::size_t i = 2 * std::size_t(offsets_[c] + k);
      p_[i] = a.x(), p_[i + 1] = a.y();
    }
  }
}

double CorotationalFrames::Turn::angle() const {
  return std::atan2(skew, trace);
}

const double* CorotationalFrames::relative(int c, const SplitDofMap& dofs,
                                           const Eigen::VectorXd& u) const {
  // The check runs after every step: no allocation per cell. A std::vector keeps its capacity
  // when resized; an Eigen vector reallocates at every change of size, so at every other cell.
  thread_local std::vector<double> w;
  const int n = cell_size(c);
  w.resize(2 * n);
  const double ox = u[2 * dofs.node(c, 0)], oy = u[2 * dofs.node(c, 0) + 1];
  for (int k = 0; k < n; ++k) {
    w[2 * k] = u[2 * dofs.node(c, k)] - ox;
    w[2 * k + 1] = u[2 * dofs.node(c, k) + 1] - oy;
  }
  return w.data();
}

double CorotationalFrames::mean_rotation(int c, const SplitDofMap& dofs,
                                         const Eigen::VectorXd& u) const {
  const Eigen::Matrix2d g = displacement_gradient(c, relative(c, dofs, u));
  return 0.5 * (g(1, 0) - g(0, 1));
}

double CorotationalFrames::largest_mean_rotation(const SplitDofMap& dofs,
                                                 const Eigen::VectorXd& u) const {
  double largest = 0.0;
  for (int c = 0; c + 1 < static_cast<int>(offsets_.size()); ++c)
    largest = std::max(largest, std::abs(mean_rotation(c, dofs, u)));
  return largest;
}

CorotationalFrames::Turn CorotationalFrames::local_displacements(int c, const SplitDofMap& dofs,
                                                                 const Eigen::VectorXd& u,
                                                                 Eigen::VectorXd& local) const {
  local.resize(2 * cell_size(c));
  return local_displacements(c, relative(c, dofs, u), local.data());
}

Eigen::Vector3d CorotationalFrames::global_stress(const Turn& t, const Eigen::Vector3d& s) {
  Eigen::Matrix2d r, sigma;
  r << t.cos, -t.sin, t.sin, t.cos;
  sigma << s[0], s[2], s[2], s[1];
  const Eigen::Matrix2d g = r * sigma * r.transpose();
  return {g(0, 0), g(1, 1), g(0, 1)};
}

}  // namespace vorodg
