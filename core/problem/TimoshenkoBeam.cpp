#include "core/problem/TimoshenkoBeam.hpp"

#include "core/util/Errors.hpp"

namespace vorodg {

TimoshenkoBeam::TimoshenkoBeam(const IsotropicElasticity& material, double length, double depth,
                               double load)
    : ExactSolution(material, {BoundaryKind::dirichlet, BoundaryKind::traction,
                               BoundaryKind::traction, BoundaryKind::traction}),
      length_(length),
      depth_(depth),
      load_(load),
      inertia_(depth * depth * depth / 12.0) {
  if (!(length > 0 && depth > 0)) throw InputError("beam: expected length and depth > 0");
  const double E = material.E(), nu = material.nu();
  const bool strain = material.model() == PlaneModel::strain;
  E_ = strain ? E / (1 - nu * nu) : E;
  nu_ = strain ? nu / (1 - nu) : nu;
}

Eigen::Vector2d TimoshenkoBeam::displacement(const Point& p) const {
  const double x = p.x(), y = p.y(), L = length_, D = depth_, nu = nu_;
  const double c = load_ / (6 * E_ * inertia_);
  return {-c * y * ((6 * L - 3 * x) * x + (2 + nu) * (y * y - D * D / 4)),
          c * (3 * nu * y * y * (L - x) + (4 + 5 * nu) * D * D * x / 4 + (3 * L - x) * x * x)};
}

Eigen::Matrix2d TimoshenkoBeam::gradient(const Point& p) const {
  const double x = p.x(), y = p.y(), L = length_, D = depth_, nu = nu_;
  const double c = load_ / (6 * E_ * inertia_);
  Eigen::Matrix2d G;
  G(0, 0) = -c * y * (6 * L - 6 * x);
  G(0, 1) = -c * ((6 * L - 3 * x) * x + (2 + nu) * (3 * y * y - D * D / 4));
  G(1, 0) = c * (-3 * nu * y * y + (4 + 5 * nu) * D * D / 4 + 6 * L * x - 3 * x * x);
  G(1, 1) = c * 6 * nu * y * (L - x);
  return G;
}

std::array<Eigen::Matrix2d, 2> TimoshenkoBeam::hessian(const Point& p) const {
  const double x = p.x(), y = p.y(), L = length_, nu = nu_;
  const double c = load_ / (6 * E_ * inertia_);
  Eigen::Matrix2d Hx, Hy;
  Hx << 6 * c * y, -c * (6 * L - 6 * x), -c * (6 * L - 6 * x), -c * (2 + nu) * 6 * y;
  Hy << c * (6 * L - 6 * x), -6 * c * nu * y, -6 * c * nu * y, 6 * c * nu * (L - x);
  return {Hx, Hy};
}

}  // namespace vorodg
