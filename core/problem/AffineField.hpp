#pragma once
// The patch test field: an affine displacement u = a + G x with a non-symmetric G (so it has a
// rotation part too). Constant stress, zero body force. Every consistent formulation reproduces
// it exactly, with all sides Dirichlet (`patch`) or with Dirichlet on left and bottom and the
// exact traction on right and top (`patch-mixed`). `patch-traction` loads every side with
// traction and so leaves rigid motions free: the singular case the solvers must refuse.
#include "core/problem/ExactSolution.hpp"

namespace vorodg {

class AffineField : public ExactSolution {
 public:
  enum class Supports { dirichlet, mixed, traction };
  AffineField(const IsotropicElasticity& material, Supports supports);

  std::string name() const override;
  Eigen::Vector2d displacement(const Point& x) const override { return offset_ + G_ * x; }
  Eigen::Matrix2d gradient(const Point&) const override { return G_; }
  std::array<Eigen::Matrix2d, 2> hessian(const Point&) const override {
    return {Eigen::Matrix2d::Zero(), Eigen::Matrix2d::Zero()};
  }

 private:
  Supports supports_;
  Eigen::Vector2d offset_{1e-3, -2e-3};
  Eigen::Matrix2d G_ = (Eigen::Matrix2d() << 2e-3, 1e-3, -5e-4, -1e-3).finished();
};

}  // namespace vorodg
