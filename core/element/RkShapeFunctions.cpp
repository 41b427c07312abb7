#include "core/element/RkShapeFunctions.hpp"

#include <Eigen/Dense>

namespace vorodg {

double rk_shape_functions(const RkCellFrame& frame, std::span<const Eigen::Vector2d> nodes,
                          const Eigen::Vector2d& x, const double* w, const Eigen::Vector2d* grad_w,
                          double* psi, Eigen::Vector2d* grad_psi) {
  const int n = static_cast<int>(nodes.size());
  auto basis = [&](const Eigen::Vector2d& y) {
    return Eigen::Vector3d(1.0, (y.x() - frame.centre.x()) / frame.scale,
                           (y.y() - frame.centre.y()) / frame.scale);
  };
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero(),
                  dM[2] = {Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero()};
  for (int J = 0; J < n; ++J) {
    const Eigen::Vector3d pJ = basis(nodes[J]);
    const Eigen::Matrix3d ppT = pJ * pJ.transpose();
    M += w[J] * ppT;
    dM[0] += grad_w[J].x() * ppT;
    dM[1] += grad_w[J].y() * ppT;
  }
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
  const Eigen::Vector3d b = solve(basis(x));  // M^-1 p(x)
  Eigen::Vector3d c[2];                       // M^-1 dp/dx_d - M^-1 dM_d M^-1 p(x)
  for (int d = 0; d < 2; ++d) {
    Eigen::Vector3d dp = Eigen::Vector3d::Zero();
    dp[1 + d] = 1.0 / frame.scale;
    c[d] = solve(dp - dM[d] * b);
  }
  for (int I = 0; I < n; ++I) {
    const Eigen::Vector3d pI = basis(nodes[I]);
    const double modulation = b.dot(pI);
    psi[I] = modulation * w[I];
    grad_psi[I] = Eigen::Vector2d(c[0].dot(pI), c[1].dot(pI)) * w[I] + modulation * grad_w[I];
  }
  return rcond;
}

}  // namespace vorodg
