#include "core/material/CohesiveLaw.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

void require(bool ok, const char* what, double value, const char* expected) {
  if (!ok)
    throw InputError(std::string("cohesive law: ") + what + " = " + std::to_string(value) +
                     ", expected " + expected);
}

}  // namespace

CohesiveLaw::CohesiveLaw(const CohesiveParameters& parameters) : p_(parameters) {
  require(std::isfinite(p_.strength) && p_.strength > 0, "strength", p_.strength, "> 0");
  require(std::isfinite(p_.fracture_energy) && p_.fracture_energy > 0, "fracture_energy",
          p_.fracture_energy, "> 0");
  require(std::isfinite(p_.shear_factor) && p_.shear_factor >= 0, "shear_factor", p_.shear_factor,
          ">= 0");
}

double CohesiveLaw::critical_opening() const {
  const double scale = p_.fracture_energy / p_.strength;
  return p_.shape == SofteningShape::linear ? 2.0 * scale : 3.6 * scale;
}

double CohesiveLaw::kink_opening() const {
  return 0.8 * p_.fracture_energy / p_.strength;
}

double CohesiveLaw::envelope_slope(double opening) const {
  const double sc = p_.strength, dc = critical_opening();
  if (opening >= dc) return 0.0;
  if (p_.shape == SofteningShape::linear) return -sc / dc;
  const double d1 = kink_opening();
  return opening < d1 ? -(2.0 / 3.0) * sc / d1 : -(sc / 3.0) / (dc - d1);
}

double CohesiveLaw::envelope(double opening) const {
  const double sc = p_.strength, dc = critical_opening();
  if (opening >= dc) return 0.0;
  if (p_.shape == SofteningShape::linear) return sc * (1.0 - opening / dc);
  const double d1 = kink_opening();
  return opening < d1 ? sc * (1.0 - (2.0 / 3.0) * opening / d1)
                      : (sc / 3.0) * (dc - opening) / (dc - d1);
}

CohesiveLaw::Response CohesiveLaw::respond(const Eigen::Vector2d& opening, State& state) const {
  if (!opening.allFinite()) throw NumericalError("cohesive law: the opening is not finite");
  Response r;
  const bool open = opening[0] > 0.0;
  const double beta2 = p_.shear_factor * p_.shear_factor;
  // W maps the opening to the vector the traction is parallel to: (<delta_n>, beta^2 delta_t).
  const Eigen::Matrix2d W = Eigen::Vector2d(open ? 1.0 : 0.0, beta2).asDiagonal();
  const Eigen::Vector2d w = W * opening;
  const double delta = std::sqrt(std::max(opening[0], 0.0) * std::max(opening[0], 0.0) +
                                 beta2 * opening[1] * opening[1]);
  r.effective_opening = delta;
  r.traction.setZero();
  r.tangent.setZero();
  if (delta <= 0.0) return r;  // no opening: the traction's direction is undefined, take none
  r.loading = delta >= state.max_opening;
  if (r.loading) {
    state.max_opening = delta;
    const double T = envelope(delta), slope = envelope_slope(delta);
    r.traction = (T / delta) * w;
    // d(T/delta)/d(opening) = (T' delta - T) / delta^2 * W opening / delta
    r.tangent =
        (T / delta) * W + ((slope * delta - T) / (delta * delta * delta)) * w * w.transpose();
  } else {
    const double secant = envelope(state.max_opening) / state.max_opening;
    r.traction = secant * w;
    r.tangent = secant * W;
  }
  return r;
}

double CohesiveLaw::dissipated_energy(double max_opening) const {
  const double dc = critical_opening();
  if (max_opening >= dc) return p_.fracture_energy;
  if (max_opening <= 0.0) return 0.0;
  // Area under the envelope up to max_opening (trapezoids on its linear pieces), less the
  // triangle that unloading to the origin gives back.
  double area = 0.0;
  if (p_.shape == SofteningShape::bilinear && max_opening > kink_opening()) {
    const double d1 = kink_opening();
    area = 0.5 * (p_.strength + envelope(d1)) * d1 +
           0.5 * (envelope(d1) + envelope(max_opening)) * (max_opening - d1);
  } else {
    area = 0.5 * (p_.strength + envelope(max_opening)) * max_opening;
  }
  return area - 0.5 * envelope(max_opening) * max_opening;
}

}  // namespace vorodg
