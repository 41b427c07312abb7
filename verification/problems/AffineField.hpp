#pragma once
// The patch test field: an affine displacement u = a + G x with a non-symmetric G (so it has a
// rotation part too). Constant stress, zero body force. Every consistent formulation reproduces
// it exactly, with all sides Dirichlet (`patch`) or with Dirichlet on left and bottom and the
// exact traction on right and top (`patch-mixed`). `patch-traction` loads every side with
// traction and so leaves rigid motions free: the singular case the solvers must refuse.
#include "verification/problems/ExactSolution.hpp"

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

/// A smooth manufactured field with body force on any rectangle, zero on all four sides
/// (all-Dirichlet): u = U (s, s/2), s = sin(pi X/W) sin(pi Y/H), X, Y measured from the lower
/// left corner. For convergence runs without the beam's boundary layer of tractions.
class ManufacturedSolution : public ExactSolution {
 public:
  ManufacturedSolution(const IsotropicElasticity& material, const Rectangle& domain,
                       double amplitude = 1e-3);

  std::string name() const override { return "mms"; }
  Eigen::Vector2d displacement(const Point& x) const override;
  Eigen::Matrix2d gradient(const Point& x) const override;
  std::array<Eigen::Matrix2d, 2> hessian(const Point& x) const override;

 private:
  Rectangle domain_;
  double amplitude_, a_, b_;
};

}  // namespace vorodg
