#include "fracture/CohesiveLaw.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/util/Errors.hpp"
#include "fracture/SofteningLaws.hpp"

namespace vorodg {

CohesiveLaw::CohesiveLaw(const CohesiveParameters& parameters) : p_(parameters) {
  require_parameter(std::isfinite(p_.strength) && p_.strength > 0, "strength", p_.strength, "> 0");
  require_parameter(std::isfinite(p_.fracture_energy) && p_.fracture_energy > 0, "fracture_energy",
                    p_.fracture_energy, "> 0");
  require_parameter(std::isfinite(p_.shear_factor) && p_.shear_factor >= 0, "shear_factor",
                    p_.shear_factor, ">= 0");
  require_parameter(std::isfinite(p_.initial_stiffness) && p_.initial_stiffness >= 0,
                    "initial_stiffness", p_.initial_stiffness, ">= 0");
  const double sc = p_.strength;
  const double d0 = intrinsic() ? sc / p_.initial_stiffness : 0.0;
  if (intrinsic()) knots_.emplace_back(0.0, 0.0);
  knots_.emplace_back(d0, sc);
  for (const Eigen::Vector2d& knot :
       softening_law(p_.shape).knots_after_peak(sc, p_.fracture_energy, d0))
    knots_.push_back(knot);
  for (std::size_t k = 1; k < knots_.size(); ++k)
    require_parameter(knots_[k].x() > knots_[k - 1].x(), "initial_stiffness", p_.initial_stiffness,
                      "large enough that the peak comes before the critical opening");
}

CohesiveLaw CohesiveLaw::with_strength_factor(double factor) const {
  CohesiveParameters scaled = p_;
  scaled.strength *= factor;
  return CohesiveLaw(scaled);
}

double CohesiveLaw::critical_opening() const {
  return knots_.back().x();
}

int CohesiveLaw::segment(double opening) const {
  for (std::size_t k = 1; k < knots_.size(); ++k)
    if (opening < knots_[k].x()) return static_cast<int>(k) - 1;
  return -1;
}

double CohesiveLaw::envelope_slope(double opening) const {
  const int k = segment(std::max(opening, 0.0));
  if (k < 0) return 0.0;
  const Eigen::Vector2d d = knots_[k + 1] - knots_[k];
  return d.y() / d.x();
}

double CohesiveLaw::envelope(double opening) const {
  opening = std::max(opening, 0.0);
  const int k = segment(opening);
  if (k < 0) return 0.0;
  return knots_[k].y() + envelope_slope(opening) * (opening - knots_[k].x());
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
  if (delta <= 0.0) {
    // No opening: an intrinsic law is on its elastic branch; an extrinsic one's traction has no
    // direction yet, so it takes none.
    if (intrinsic() && state.max_opening <= knots_[1].x()) r.tangent = p_.initial_stiffness * W;
    return r;
  }
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

double CohesiveLaw::stored_energy(const Eigen::Vector2d& opening, const State& state) const {
  const double dmax = state.max_opening;
  const double delta = std::hypot(std::max(opening[0], 0.0), p_.shear_factor * opening[1]);
  const double secant = dmax > 0.0    ? envelope(dmax) / dmax
                        : intrinsic() ? p_.initial_stiffness
                                      : 0.0;
  return 0.5 * secant * delta * delta;
}

double CohesiveLaw::dissipated_energy(double max_opening) const {
  if (max_opening >= critical_opening()) return p_.fracture_energy;
  if (max_opening <= 0.0) return 0.0;
  // Area under the envelope up to max_opening (trapezoids on its linear pieces), less the
  // triangle that unloading to the origin gives back.
  double area = 0.0;
  for (std::size_t k = 1; k < knots_.size() && knots_[k - 1].x() < max_opening; ++k) {
    const double right = std::min(knots_[k].x(), max_opening);
    area += 0.5 * (knots_[k - 1].y() + envelope(right)) * (right - knots_[k - 1].x());
  }
  return std::max(area - 0.5 * envelope(max_opening) * max_opening, 0.0);
}

}  // namespace vorodg
