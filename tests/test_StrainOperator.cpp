// The strain operator and the standard-B stiffness kernel (core/element/StrainOperator):
//   - B of one point maps a node's displacement to (eps_xx, eps_yy, 2 eps_xy) of its gradient;
//   - standard_strain_stiffness equals sum_q w_q B_q^T D B_q formed point by point, to 1e-14 of
//     its largest entry, for an anisotropic D (every entry non-zero, so each of the kernel's
//     terms is exercised) and for node counts 3 to 12, and is exactly symmetric.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <random>
#include <vector>

#include "core/element/StrainOperator.hpp"

namespace vorodg {
namespace {

TEST(StrainOperator, MapsNodeDisplacementToVoigtStrain) {
  const Eigen::Vector2d g[2] = {{0.3, -1.2}, {2.0, 0.5}};
  StrainOperator B;
  strain_operator(g, 2, B);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(4);
  u << 0.7, -0.4, 0.0, 0.0;  // node 0 moves by (0.7, -0.4)
  const Eigen::Vector3d eps = B * u;
  EXPECT_DOUBLE_EQ(eps[0], 0.3 * 0.7);
  EXPECT_DOUBLE_EQ(eps[1], -1.2 * -0.4);
  EXPECT_DOUBLE_EQ(eps[2], -1.2 * 0.7 + 0.3 * -0.4);
}

TEST(StrainOperator, StandardStiffnessEqualsPointByPointSum) {
  std::mt19937_64 rng(20261130);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::Matrix3d D;
  D << 3.0, 1.1, 0.4, 1.1, 2.5, -0.3, 0.4, -0.3, 0.9;  // symmetric, anisotropic
  for (int n = 3; n <= 12; ++n) {
    const int points = 2 * n + 1;
    std::vector<double> w(points);
    std::vector<Eigen::Vector2d> g(std::size_t(points) * n);
    for (double& x : w) x = 0.5 + 0.5 * u(rng);
    for (auto& x : g) x = {u(rng), u(rng)};
    Eigen::MatrixXd reference = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    StrainOperator B;
    for (int q = 0; q < points; ++q) {
      strain_operator(&g[std::size_t(q) * n], n, B);
      reference += w[q] * (B.transpose() * D * B);
    }
    Eigen::MatrixXd K;
    standard_strain_stiffness(w, g.data(), n, D, K);
    ASSERT_EQ(K.rows(), 2 * n);
    ASSERT_EQ(K.cols(), 2 * n);
    const double scale = reference.cwiseAbs().maxCoeff();
    EXPECT_LT((K - reference).cwiseAbs().maxCoeff(), 1e-14 * scale) << n << " nodes";
    EXPECT_EQ((K - K.transpose()).cwiseAbs().maxCoeff(), 0.0) << n << " nodes";
  }
}

}  // namespace
}  // namespace vorodg
