#include "core/material/IsotropicElasticity.hpp"

#include <cmath>

#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"

namespace vorodg {

IsotropicElasticity::IsotropicElasticity(double E, double nu, PlaneModel model)
    : E_(E), nu_(nu), model_(model) {
  if (!(E > 0.0) || !std::isfinite(E))
    throw InputError("Young's modulus E = " + fmt(E) + ": expected a finite E > 0");
  if (!(nu > -1.0 && nu < 0.5))
    throw InputError("Poisson's ratio nu = " + fmt(nu, 17) + ": expected -1 < nu < 0.5");
  D_.setZero();
  if (model == PlaneModel::stress) {
    const double c = E / (1 - nu * nu);
    D_ << c, c * nu, 0, c * nu, c, 0, 0, 0, c * (1 - nu) / 2;
  } else {
    const double l = lambda(), m = mu();
    D_ << l + 2 * m, l, 0, l, l + 2 * m, 0, 0, 0, m;
  }
}

double IsotropicElasticity::von_mises(const Eigen::Vector3d& s) const {
  const double szz = model_ == PlaneModel::strain ? nu_ * (s[0] + s[1]) : 0.0;
  const double a = s[0] - s[1], b = s[1] - szz, c = szz - s[0];
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3 * s[2] * s[2]);
}

}  // namespace vorodg
