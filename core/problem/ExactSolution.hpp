#pragma once
// A boundary value problem with a known displacement field (deal.II's "problem data as small
// named classes"). Derived classes give u, grad u and the second derivatives; stress, tractions
// on the sides and the body force -div(sigma) follow from the material here, once.
#include <Eigen/Core>
#include <array>

#include "core/material/IsotropicElasticity.hpp"
#include "core/problem/BoundaryValueProblem.hpp"

namespace vorodg {

class ExactSolution : public BoundaryValueProblem {
 public:
  ExactSolution(const IsotropicElasticity& material, std::array<BoundaryKind, 4> sides)
      : material_(material), sides_(sides) {}

  virtual Eigen::Vector2d displacement(const Point& x) const = 0;
  /// grad u: G(i, j) = d u_i / d x_j.
  virtual Eigen::Matrix2d gradient(const Point& x) const = 0;
  /// Second derivatives: H[i](j, k) = d^2 u_i / dx_j dx_k.
  virtual std::array<Eigen::Matrix2d, 2> hessian(const Point& x) const = 0;

  /// Voigt strain (eps_xx, eps_yy, 2 eps_xy) and stress.
  Eigen::Vector3d strain(const Point& x) const;
  Eigen::Vector3d stress(const Point& x) const { return material_.D() * strain(x); }

  BoundaryKind boundary(Side s) const override { return sides_[static_cast<int>(s)]; }
  Eigen::Vector2d dirichlet_value(const Point& x) const override { return displacement(x); }
  Eigen::Vector2d traction(const Point& x, const Eigen::Vector2d& n) const override;
  Eigen::Vector2d body_force(const Point& x) const override;
  const IsotropicElasticity& material() const { return material_; }

 protected:
  IsotropicElasticity material_;
  std::array<BoundaryKind, 4> sides_;  // left, right, bottom, top
};

}  // namespace vorodg
