#include "core/element/VirtualElement.hpp"

namespace vorodg {
VemProjection::VemProjection(std::span<const Eigen::Vector2d> nodes, double area)
    : n_(static_cast<int>(nodes.size())), mean_(Eigen::Vector2d::Zero()) {
  for (const auto& v : nodes) mean_ += v;
  mean_ /= static_cast<double>(n_);
  for (int k = 0; k < n_; ++k) {
    // psi_k is the hat of vertex k on its two edges: each contributes half its length times
    // its outward normal, (dy, -dx) / 2 of the edge vector.
    const Eigen::Vector2d& prev = nodes[(k + n_ - 1) % n_];
    const Eigen::Vector2d& next = nodes[(k + 1) % n_];
    gradients_[k] =
        Eigen::Vector2d(0.5 * (next.y() - prev.y()), 0.5 * (prev.x() - next.x())) / area;
  }
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
