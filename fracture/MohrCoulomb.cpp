#include "fracture/MohrCoulomb.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/util/Errors.hpp"

namespace vorodg {

MohrCoulomb::MohrCoulomb(const MohrCoulombParameters& parameters) : p_(parameters) {
  require_parameter(std::isfinite(p_.cohesion) && p_.cohesion > 0, "cohesion", p_.cohesion, "> 0");
  require_parameter(std::isfinite(p_.friction) && p_.friction >= 0, "friction", p_.friction,
                    ">= 0");
  require_parameter(std::isfinite(p_.tensile_cutoff) && p_.tensile_cutoff > 0, "tensile_cutoff",
                    p_.tensile_cutoff, "> 0");
  circle_reach_ = std::sqrt(1.0 + p_.friction * p_.friction);
}

double MohrCoulomb::utilization(double normal, double shear) const {
  if (!std::isfinite(normal) || !std::isfinite(shear))
    throw NumericalError("Mohr-Coulomb criterion: the traction is not finite");
  const double tension = normal / p_.tensile_cutoff;
  const double capacity = p_.cohesion - p_.friction * normal;  // the shear the plane can carry
  const double sliding =
      capacity > 0.0 ? std::abs(shear) / capacity : std::numeric_limits<double>::infinity();
  return std::max(tension, sliding);
}

double MohrCoulomb::worst_plane_factor(double sxx, double syy, double sxy) const {
  const double d = 0.5 * (sxx - syy);
  const double p = 0.5 * (sxx + syy), R = std::sqrt(d * d + sxy * sxy);  // no overflow at stresses
  return std::max((p + R) / p_.tensile_cutoff, (p_.friction * p + R * circle_reach_) / p_.cohesion);
}

}  // namespace vorodg
