#include "core/element/VirtualElement.hpp"

#include "core/geometry/Polygon.hpp"

namespace vorodg {

VemProjection::VemProjection(std::span<const Eigen::Vector2d> nodes, double area)
    : n_(static_cast<int>(nodes.size())), mean_(Eigen::Vector2d::Zero()) {
  for (const auto& v : nodes) mean_ += v;
  mean_ /= static_cast<double>(n_);
  for (int k = 0; k < n_; ++k)  // the boundary integral of the hat of vertex k, over the area
    gradients_[k] = polygon::vertex_hat_flux(nodes[(k + n_ - 1) % n_], nodes[(k + 1) % n_]) / area;
}

void VemProjection::basis(const Eigen::Vector2d& x, double* psi, Eigen::Vector2d* grad) const {
  const Eigen::Vector2d offset = x - mean_;
  for (int k = 0; k < n_; ++k) {
    grad[k] = gradients_[k];
    psi[k] = 1.0 / n_ + gradients_[k].dot(offset);
  }
}

Eigen::MatrixXd vem_stabilization_pattern(std::span<const Eigen::Vector2d> nodes, double area) {
  const int n = static_cast<int>(nodes.size());
  const VemProjection projection(nodes, area);
  Eigen::MatrixXd complement = Eigen::MatrixXd::Identity(n, n);  // I - P
  Eigen::Vector2d grad[64];
  double psi[64];
  for (int j = 0; j < n; ++j) {
    projection.basis(nodes[j], psi, grad);
    for (int k = 0; k < n; ++k) complement(j, k) -= psi[k];
  }
  return complement.transpose() * complement;
}

}  // namespace vorodg
