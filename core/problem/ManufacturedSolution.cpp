#include "core/problem/ManufacturedSolution.hpp"

#include <cmath>
#include <numbers>

namespace vorodg {

ManufacturedSolution::ManufacturedSolution(const IsotropicElasticity& material,
                                           const Rectangle& domain, double amplitude)
    : ExactSolution(material, {BoundaryKind::dirichlet, BoundaryKind::dirichlet,
                               BoundaryKind::dirichlet, BoundaryKind::dirichlet}),
      domain_(domain),
      amplitude_(amplitude),
      a_(std::numbers::pi / domain.width()),
      b_(std::numbers::pi / domain.height()) {}

Eigen::Vector2d ManufacturedSolution::displacement(const Point& p) const {
  const double s = std::sin(a_ * (p.x() - domain_.x0())) * std::sin(b_ * (p.y() - domain_.y0()));
  return amplitude_ * Eigen::Vector2d(s, 0.5 * s);
}

Eigen::Matrix2d ManufacturedSolution::gradient(const Point& p) const {
  const double X = a_ * (p.x() - domain_.x0()), Y = b_ * (p.y() - domain_.y0());
  const Eigen::Vector2d ds(a_ * std::cos(X) * std::sin(Y), b_ * std::sin(X) * std::cos(Y));
  Eigen::Matrix2d G;
  G.row(0) = ds.transpose();
  G.row(1) = 0.5 * ds.transpose();
  return amplitude_ * G;
}

std::array<Eigen::Matrix2d, 2> ManufacturedSolution::hessian(const Point& p) const {
  const double X = a_ * (p.x() - domain_.x0()), Y = b_ * (p.y() - domain_.y0());
  const double s = std::sin(X) * std::sin(Y), sxy = a_ * b_ * std::cos(X) * std::cos(Y);
  Eigen::Matrix2d H;
  H << -a_ * a_ * s, sxy, sxy, -b_ * b_ * s;
  return {amplitude_ * H, 0.5 * amplitude_ * H};
}

}  // namespace vorodg
