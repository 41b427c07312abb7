#pragma once
// Reproducing-kernel shape functions with a linear basis (report Eqs. 2-10), on one cell:
//   psi_I(x) = p(x)^T M(x)^-1 p(x_I) w_I(x),   M(x) = sum_J w_J(x) p(x_J) p(x_J)^T,
// with the basis p(y) = (1, (y - x_c)/h, ...) centred and scaled by the cell for conditioning.
// This form reproduces every linear field exactly: sum_I psi_I p(x_I)^T = p(x)^T.
// Gradients by differentiating it (the standard RK derivative formula):
//   d psi_I = [(M^-1 dp - M^-1 dM M^-1 p) . p_I] w_I + (M^-1 p . p_I) dw_I.
#include <Eigen/Core>
#include <span>

namespace vorodg {

struct RkCellFrame {
  Eigen::Vector2d centre;  // x_c
  double scale = 1.0;      // h
};

/// Shape functions and gradients of the n nodes at a point x strictly inside a cell (where at
/// least three non-collinear nodes have positive weight). Returns the reciprocal 1-norm condition
/// number of M so callers can guard against breakdown (0 or NaN when M is singular).
double rk_shape_functions(const RkCellFrame& frame, std::span<const Eigen::Vector2d> nodes,
                          const Eigen::Vector2d& x, const double* w, const Eigen::Vector2d* grad_w,
                          double* psi, Eigen::Vector2d* grad_psi);

/// The basis at the nodes, p(x_J): the same for every point of a cell, so a cell's points can
/// share it (the overload below).
void rk_node_basis(const RkCellFrame& frame, std::span<const Eigen::Vector2d> nodes,
                   Eigen::Vector3d* basis);
/// The same shape functions from the nodes' basis (rk_node_basis), to the same bits.
double rk_shape_functions(const RkCellFrame& frame, std::span<const Eigen::Vector3d> node_basis,
                          const Eigen::Vector2d& x, const double* w, const Eigen::Vector2d* grad_w,
                          double* psi, Eigen::Vector2d* grad_psi);

}  // namespace vorodg
