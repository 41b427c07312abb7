#include "dynamics/contact/ContactFriction.hpp"

#include <cmath>

#include "core/util/Errors.hpp"

namespace vorodg {

ContactFriction::ContactFriction(double mu, const std::string& what) : mu_(mu) {
  require_parameter(std::isfinite(mu) && mu >= 0.0 && mu <= 10.0, what, mu,
                    "in [0, 10] (0: frictionless)");
}

Point ContactFriction::force(const Point& normal, const Point& relative_velocity,
                             const PenaltyContact::Response& pushed, const PairState& state,
                             double& shear, ContactReport& report, const char* who) const {
  if (state.velocity.empty())
    throw InputError(std::string(who) + ": friction needs the velocity of every pair: found none");
  const Point tangent(-normal.y(), normal.x());
  // The step's tangential motion; none when the positions are the last evaluation's.
  const double increment = (state.repeated ? 0.0 : state.dt) * relative_velocity.dot(tangent);
  const CoulombReturn c = respond(shear, increment, pushed.force, pushed.stiffness);
  shear = c.shear;
  report.potential += stored_energy(c.shear, pushed.stiffness);
  report.friction_dissipated += c.dissipated;
  report.sliding += c.slipping();
  return c.shear * tangent;
}

}  // namespace vorodg
