#include "core/element/RkShapeFunctions.hpp"

#include <Eigen/Dense>
#include <array>
#include <stdexcept>

namespace vorodg {

namespace {

Eigen::Vector3d basis_at(const RkCellFrame& frame, const Eigen::Vector2d& y) {
  return {1.0, (y.x() - frame.centre.x()) / frame.scale, (y.y() - frame.centre.y()) / frame.scale};
}

/// The upper triangle of p p^T, row by row: (00, 01, 02, 11, 12, 22).
using Sym3 = std::array<double, 6>;

Sym3 outer_upper(const Eigen::Vector3d& p) {
  return {p[0] * p[0], p[0] * p[1], p[0] * p[2], p[1] * p[1], p[1] * p[2], p[2] * p[2]};
}

Eigen::Matrix3d from_upper(const Sym3& a) {
  Eigen::Matrix3d A;
  A << a[0], a[1], a[2], a[1], a[3], a[4], a[2], a[4], a[5];
  return A;
}

}  // namespace

void rk_node_basis(const RkCellFrame& frame, std::span<const Eigen::Vector2d> nodes,
                   Eigen::Vector3d* basis) {
  for (std::size_t J = 0; J < nodes.size(); ++J) basis[J] = basis_at(frame, nodes[J]);
}

double rk_shape_functions(const RkCellFrame& frame, std::span<const Eigen::Vector2d> nodes,
                          const Eigen::Vector2d& x, const double* w, const Eigen::Vector2d* grad_w,
                          double* psi, Eigen::Vector2d* grad_psi) {
  constexpr std::size_t kMax = 64;
  if (nodes.size() > kMax) throw std::length_error("rk_shape_functions: more than 64 nodes");
  Eigen::Vector3d basis[kMax];
  rk_node_basis(frame, nodes, basis);
  return rk_shape_functions(frame, {basis, nodes.size()}, x, w, grad_w, psi, grad_psi);
}

double rk_shape_functions(const RkCellFrame& frame, std::span<const Eigen::Vector3d> node_basis,
                          const Eigen::Vector2d& x, const double* w, const Eigen::Vector2d* grad_w,
                          double* psi, Eigen::Vector2d* grad_psi) {
  const int n = static_cast<int>(node_basis.size());
  // M = sum_J w_J p_J p_J^T and its derivatives, accumulated in local sums (which stay in
  // registers; a matrix updated entry by entry in memory made every addition wait on the last).
  Sym3 m{}, dmx{}, dmy{};
  for (int J = 0; J < n; ++J) {
    const Sym3 q = outer_upper(node_basis[J]);
    const double wj = w[J], gx = grad_w[J].x(), gy = grad_w[J].y();
    for (int k = 0; k < 6; ++k) {
      m[k] += wj * q[k];
      dmx[k] += gx * q[k];
      dmy[k] += gy * q[k];
    }
  }
  const Eigen::Matrix3d M = from_upper(m), dM[2] = {from_upper(dmx), from_upper(dmy)};
  // M is 3x3 symmetric positive definite inside the cell: its inverse in closed form (adjugate
  // over determinant) is exact enough and far cheaper than a factorization per point.
  const Eigen::Matrix3d Minv = M.inverse();
  const double rcond =
      1.0 / (M.cwiseAbs().colwise().sum().maxCoeff() * Minv.cwiseAbs().colwise().sum().maxCoeff());
  // One step of iterative refinement makes the solves backward stable, which is what keeps
  // partition of unity and linear reproduction at round-off level near the cell's edges,
  // where M is ill-conditioned.
  auto solve = [&](const Eigen::Vector3d& rhs) {
    Eigen::Vector3d y = Minv * rhs;
    return Eigen::Vector3d(y + Minv * (rhs - M * y));
  };
  const Eigen::Vector3d b = solve(basis_at(frame, x));  // M^-1 p(x)
  Eigen::Vector3d c[2];                                 // M^-1 dp/dx_d - M^-1 dM_d M^-1 p(x)
  for (int d = 0; d < 2; ++d) {
    Eigen::Vector3d dp = Eigen::Vector3d::Zero();
    dp[1 + d] = 1.0 / frame.scale;
    c[d] = solve(dp - dM[d] * b);
  }
  for (int I = 0; I < n; ++I) {
    const Eigen::Vector3d& pI = node_basis[I];
    const double modulation = b.dot(pI);
    psi[I] = modulation * w[I];
    grad_psi[I] = Eigen::Vector2d(c[0].dot(pI), c[1].dot(pI)) * w[I] + modulation * grad_w[I];
  }
  return rcond;
}

}  // namespace vorodg
