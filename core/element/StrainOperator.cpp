#include "core/element/StrainOperator.hpp"

#include <vector>

namespace vorodg {

void strain_operator(const Eigen::Vector2d* gradients, int n, StrainOperator& B) {
  B.setZero(3, 2 * n);
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d& g = gradients[k];
    B(0, 2 * k) = g.x();
    B(1, 2 * k + 1) = g.y();
    B(2, 2 * k) = g.y();
    B(2, 2 * k + 1) = g.x();
  }
}

// Node j's columns of B are [[gx, 0], [0, gy], [gy, gx]], so each 2 x 2 block of
// sum_q w_q B_j^T D B_k is a fixed combination of the weighted gradient products
// G_ab(j, k) = sum_q w_q (d_a psi_j)(d_b psi_k). Forming the three distinct G's takes about a
// quarter of the arithmetic of B^T D B at every point, and no temporaries.
void standard_strain_stiffness(std::span<const double> weights, const Eigen::Vector2d* gradients,
                               int n, const Eigen::Matrix3d& D, Eigen::MatrixXd& K) {
  thread_local std::vector<double> products;
  products.assign(3 * std::size_t(n) * n, 0.0);
  double* gxx = products.data();  // lower triangles (k <= j) of the symmetric G_xx and G_yy
  double* gyy = gxx + n * n;
  double* gxy = gyy + n * n;  // all of G_xy; G_yx(j, k) = G_xy(k, j)
  for (std::size_t q = 0; q < weights.size(); ++q) {
    const Eigen::Vector2d* g = gradients + q * n;
    for (int j = 0; j < n; ++j) {
      const double wx = weights[q] * g[j].x(), wy = weights[q] * g[j].y();
      for (int k = 0; k <= j; ++k) {
        gxx[j * n + k] += wx * g[k].x();
        gyy[j * n + k] += wy * g[k].y();
      }
      for (int k = 0; k < n; ++k) gxy[j * n + k] += wx * g[k].y();
    }
  }
  const double d11 = D(0, 0), d12 = D(0, 1), d13 = D(0, 2), d22 = D(1, 1), d23 = D(1, 2),
               d33 = D(2, 2);
  K.resize(2 * n, 2 * n);
  for (int j = 0; j < n; ++j)
    for (int k = 0; k <= j; ++k) {
      const double xx = gxx[j * n + k], yy = gyy[j * n + k];
      const double xy = gxy[j * n + k], yx = gxy[k * n + j];
      const double b00 = d11 * xx + d13 * (xy + yx) + d33 * yy;  // x-x block entry
      const double b01 = d12 * xy + d13 * xx + d23 * yy + d33 * yx;
      const double b10 = d12 * yx + d13 * xx + d23 * yy + d33 * xy;
      const double b11 = d22 * yy + d23 * (xy + yx) + d33 * xx;
      K(2 * j, 2 * k) = K(2 * k, 2 * j) = b00;
      K(2 * j, 2 * k + 1) = K(2 * k + 1, 2 * j) = b01;
      K(2 * j + 1, 2 * k) = K(2 * k, 2 * j + 1) = b10;
      K(2 * j + 1, 2 * k + 1) = K(2 * k + 1, 2 * j + 1) = b11;
    }
}

}  // namespace vorodg
