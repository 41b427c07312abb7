// The first-order virtual element's projection and stabilization (core/element/VirtualElement):
// 1. The projected basis is a partition of unity with linear precision: sum psi = 1,
//    sum psi v = x, sum grad = 0, sum v (x) grad = I (to 1e-12), on convex and non-convex cells.
// 2. The stabilization pattern (I - P)^T (I - P) vanishes on the vertex values of every linear
//    field and is positive on the rest: its null space is exactly the 3 linear patterns.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <vector>

#include "core/element/VirtualElement.hpp"

namespace vorodg {
namespace {

using Polygon = std::vector<Eigen::Vector2d>;

double area(const Polygon& p) {
  double a = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const auto& u = p[k];
    const auto& v = p[(k + 1) % p.size()];
    a += 0.5 * (u.x() * v.y() - u.y() * v.x());
  }
  return a;
}

std::vector<Polygon> polygons() {
  return {{{0, 0}, {1, 0}, {0.3, 0.8}},
          {{0, 0}, {2, 0}, {2, 1}, {0, 1}},
          {{0.1, 0}, {1, -0.2}, {1.6, 0.5}, {1.1, 1.3}, {0.2, 1.0}, {-0.3, 0.4}},
          {{-1, -1}, {0, -0.3}, {1, -1}, {0, 1}}};  // non-convex (an arrow head)
}

TEST(VirtualElement, ProjectionReproducesLinearFields) {
  for (const Polygon& p : polygons()) {
    const int n = static_cast<int>(p.size());
    const VemProjection projection(p, area(p));
    for (const Eigen::Vector2d& x : {Eigen::Vector2d(0.4, 0.2), Eigen::Vector2d(-3.0, 7.0)}) {
      std::vector<double> psi(n);
      std::vector<Eigen::Vector2d> grad(n);
      projection.basis(x, psi.data(), grad.data());
      double sum = 0.0;
      Eigen::Vector2d reproduced = Eigen::Vector2d::Zero(), grad_sum = Eigen::Vector2d::Zero();
      Eigen::Matrix2d identity = Eigen::Matrix2d::Zero();
      for (int k = 0; k < n; ++k) {
        sum += psi[k];
        reproduced += psi[k] * p[k];
        grad_sum += grad[k];
        identity += p[k] * grad[k].transpose();
      }
      EXPECT_NEAR(sum, 1.0, 1e-12) << n;
      EXPECT_LT((reproduced - x).norm(), 1e-12) << n;
      EXPECT_LT(grad_sum.norm(), 1e-12) << n;
      EXPECT_LT((identity - Eigen::Matrix2d::Identity()).norm(), 1e-12) << n;
    }
  }
}

TEST(VirtualElement, StabilizationSeesAllButTheLinearPatterns) {
  for (const Polygon& p : polygons()) {
    const int n = static_cast<int>(p.size());
    const Eigen::MatrixXd S = vem_stabilization_pattern(p, area(p));
    Eigen::MatrixXd linear(n, 3);
    for (int k = 0; k < n; ++k) linear.row(k) << 1.0, p[k].x(), p[k].y();
    EXPECT_LT((S * linear).norm(), 1e-12 * linear.norm()) << n;  // S is O(1): P is dimensionless
    const Eigen::VectorXd eigenvalues =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(S).eigenvalues();
    for (int k = 0; k < n; ++k) {
      if (k < 3)
        EXPECT_LT(std::abs(eigenvalues[k]), 1e-12) << n;
      else
        EXPECT_GT(eigenvalues[k], 1e-3) << n;  // ascending: the first three are the null space
    }
  }
}

}  // namespace
}  // namespace vorodg
