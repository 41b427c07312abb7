#include "core/element/StrainOperator.hpp"

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

}  // namespace vorodg
