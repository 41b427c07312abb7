#pragma once
// A smooth manufactured field with body force on any rectangle, zero on all four sides
// (all-Dirichlet): u = U (s, s/2), s = sin(pi X/W) sin(pi Y/H), X, Y measured from the lower
// left corner. For convergence runs without the beam's boundary layer of tractions.
#include "core/problem/ExactSolution.hpp"

namespace vorodg {

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
