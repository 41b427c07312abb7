#pragma once
// The lowest-order virtual element on a polygon (Beirao da Veiga et al.): the nodal basis is not
// known inside the cell, only its projection onto linear functions, which the vertex values
// determine exactly through the boundary (the basis is linear on every edge):
//   grad Pi psi_k = (1/|E|) int_dE psi_k n ds   (constant: half the two edge normals at vertex k),
//   Pi psi_k(x)   = 1/n + grad Pi psi_k . (x - x_v),   x_v the mean of the vertices.
// The stiffness is the projection's (exact with any quadrature, the consistency part) plus a
// stabilization that acts only on what the projection misses (I - P): it keeps the
// non-linear vertex patterns from being zero-energy modes, and vanishes on linear fields, so the
// patch test holds for every stabilization scale.
#include <Eigen/Core>
#include <span>

namespace vorodg {

/// The projection of a cell's nodal basis onto linear functions, made once per cell.
class VemProjection {
 public:
  /// For the polygon `nodes` (counter-clockwise, at most 64 vertices) of area `area`.
  VemProjection(std::span<const Eigen::Vector2d> nodes, double area);
  /// Pi psi_k at x, and its (constant) gradient, for every vertex k.
  void basis(const Eigen::Vector2d& x, double* psi, Eigen::Vector2d* grad) const;

 private:
  int n_;
  Eigen::Vector2d mean_;           // of the vertices
  Eigen::Vector2d gradients_[64];  // grad Pi psi_k
};

/// (I - P)^T (I - P), n x n, with P_jk = Pi psi_k(v_j): the dofi-dofi stabilization's pattern
/// for one displacement component.
Eigen::MatrixXd vem_stabilization_pattern(std::span<const Eigen::Vector2d> nodes, double area);

}  // namespace vorodg
