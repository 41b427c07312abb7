#include "core/element/LatticeStiffness.hpp"

#include <cmath>

#include "core/quadrature/TriangleRule.hpp"

namespace vorodg {
namespace {

/// Reference integrals R_ab(i, j) = int d_a phi_i d_b phi_j over the reference triangle, for the
/// (xi, eta) derivatives a, b, and int phi_i: a sub-triangle's matrices are a combination of
/// them with its metric, so no quadrature runs per sub-triangle.
struct ReferenceIntegrals {
  Eigen::Matrix<double, 6, 6> R[2][2];
  Eigen::Matrix<double, 6, 1> mass;
};

ReferenceIntegrals make_reference(int degree) {
  ReferenceIntegrals ref;
  for (auto& row : ref.R)
    for (auto& m : row) m.setZero();
  ref.mass.setZero();
  const int n = degree == 1 ? 3 : 6;
  const TriangleRule& rule = triangle_rule(3);  // exact: the integrands are quadratic at most
  for (int q = 0; q < rule.size(); ++q) {
    double phi[6], dphi[6][2];
    lattice_basis(degree, rule.bary[q][1], rule.bary[q][2], phi, dphi);
    const double w = 0.5 * rule.weights[q];  // the reference triangle's area is 1/2
    for (int i = 0; i < n; ++i) {
      ref.mass[i] += w * phi[i];
      for (int j = 0; j < n; ++j)
        for (int a = 0; a < 2; ++a)
          for (int b = 0; b < 2; ++b) ref.R[a][b](i, j) += w * dphi[i][a] * dphi[j][b];
    }
  }
  return ref;
}

const ReferenceIntegrals& reference_integrals(int degree) {
  static const ReferenceIntegrals p1 = make_reference(1), p2 = make_reference(2);
  return degree == 1 ? p1 : p2;
}

}  // namespace

SubTriangleMatrices sub_triangle_matrices(const Point& C, const Point& A, const Point& B, int m,
                                          int degree) {
  const Eigen::Matrix2d J = sub_triangle_jacobian(C, A, B, m, true);
  const double det = std::abs(J.determinant());
  const Eigen::Matrix2d Jinv = J.inverse();
  const Eigen::Matrix2d metric = det * Jinv * Jinv.transpose();  // |J| J^-1 J^-T
  const ReferenceIntegrals& ref = reference_integrals(degree);
  SubTriangleMatrices out;
  out.K = metric(0, 0) * ref.R[0][0] + metric(0, 1) * (ref.R[0][1] + ref.R[1][0]) +
          metric(1, 1) * ref.R[1][1];
  out.f = det * ref.mass;
  return out;
}

}  // namespace vorodg
