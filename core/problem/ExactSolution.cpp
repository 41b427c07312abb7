#include "core/problem/ExactSolution.hpp"

namespace vorodg {

Eigen::Vector3d ExactSolution::strain(const Point& x) const {
  const Eigen::Matrix2d G = gradient(x);
  return {G(0, 0), G(1, 1), G(0, 1) + G(1, 0)};
}

Eigen::Vector2d ExactSolution::traction(const Point& x, const Eigen::Vector2d& n) const {
  const Eigen::Vector3d s = stress(x);
  return {s[0] * n.x() + s[2] * n.y(), s[2] * n.x() + s[1] * n.y()};
}

Eigen::Vector2d ExactSolution::body_force(const Point& x) const {
  // b = -div sigma with sigma = D eps(u): differentiate the Voigt stress along x and y.
  const auto H = hessian(x);
  const Eigen::Matrix3d& D = material_.D();
  Eigen::Vector3d d_strain[2];  // d eps / dx_j
  for (int j = 0; j < 2; ++j)
    d_strain[j] = Eigen::Vector3d(H[0](0, j), H[1](1, j), H[0](1, j) + H[1](0, j));
  const Eigen::Vector3d ds_dx = D * d_strain[0], ds_dy = D * d_strain[1];
  return -Eigen::Vector2d(ds_dx[0] + ds_dy[2], ds_dx[2] + ds_dy[1]);
}

}  // namespace vorodg
