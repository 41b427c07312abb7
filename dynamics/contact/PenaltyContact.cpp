#include "dynamics/contact/PenaltyContact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/util/Errors.hpp"

namespace vorodg {

PenaltyContact::PenaltyContact(const PenaltyParameters& parameters) : p_(parameters) {
  require_parameter(std::isfinite(p_.stiffness) && p_.stiffness >= 0.0, "contact stiffness",
                    p_.stiffness, ">= 0 (0: mass-scaled, alpha m / dt^2)");
  if (p_.stiffness == 0.0)
    require_parameter(p_.alpha > 0.0 && p_.alpha <= 1.0, "contact alpha", p_.alpha,
                      "in (0, 1] (1: about one step to remove a penetration)");
  require_parameter(p_.damping_ratio >= 0.0 && p_.damping_ratio <= 1.0, "contact damping ratio",
                    p_.damping_ratio, "in [0, 1]");
}

void PenaltyContact::check(const PairState& state, const char* what) const {
  const std::string where(what);
  if (needs_mass() && state.mass.empty())
    throw InputError(where + ": the contact law needs the lumped mass of every pair (" +
                     (p_.stiffness == 0.0 ? "stiffness alpha m / dt^2" : "damping") +
                     "): found none");
  if (needs_velocity() && state.velocity.empty())
    throw InputError(where + ": contact damping needs the velocity of every pair: found none");
  if ((p_.stiffness == 0.0 || p_.plastic) && !(std::isfinite(state.dt) && state.dt > 0.0))
    throw InputError(where + ": the mass-scaled contact stiffness needs dt > 0: found " +
                     std::to_string(state.dt));
}

double PenaltyContact::reduced_mass(double m_p, double m_e) {
  if (std::isinf(m_e)) return m_p;
  return m_p + m_e > 0.0 ? m_p * m_e / (m_p + m_e) : 0.0;
}

double PenaltyContact::stiffness(double mass, double dt) const {
  return p_.stiffness > 0.0 ? p_.stiffness : p_.alpha * mass / (dt * dt);
}

double PenaltyContact::damping(double stiffness, double mass) const {
  return 2.0 * p_.damping_ratio * std::sqrt(stiffness * mass);
}

PenaltyContact::Response PenaltyContact::respond(double depth, double approach_rate, double mass,
                                                 double dt) const {
  const double k = stiffness(mass, dt);
  const double rate = std::max(approach_rate, 0.0);
  const double c = p_.plastic ? mass / dt : p_.damping_ratio > 0.0 ? damping(k, mass) : 0.0;
  return {k * depth + c * rate, 0.5 * k * depth * depth, c * rate * rate, k, c * rate};
}

Point PenaltyContact::relative_velocity(const Penetration& pen, int p, int e0, int e1,
                                        const PairState& state) {
  if (state.velocity.empty()) return Point::Zero();
  const Point vq = (1.0 - pen.t) * state.velocity[e0] + pen.t * state.velocity[e1];
  return state.velocity[p] - vq;
}

double PenaltyContact::approach_rate(const Penetration& pen, int p, int e0, int e1,
                                     const PairState& state) {
  return -relative_velocity(pen, p, e0, e1, state).dot(pen.normal);
}

void PenaltyContact::distribute(const Point& f, double t, int p, int e0, int e1,
                                std::span<Point> force) {
  const Point f1 = -t * f;
  force[p] += f;
  force[e0] += -f - f1;  // written so that the three forces cancel to the last bit possible
  force[e1] += f1;
}

PenaltyContact::Response PenaltyContact::apply(const Penetration& pen, int p, int e0, int e1,
                                               const PairState& state, std::span<Point> force,
                                               std::span<Point> velocity_force) const {
  double mass = 0.0;
  if (!state.mass.empty())
    mass = reduced_mass(state.mass[p], std::min(state.mass[e0], state.mass[e1]));
  const Response r = respond(pen.depth, approach_rate(pen, p, e0, e1, state), mass, state.dt);
  distribute(r.force * pen.normal, pen.t, p, e0, e1, force);
  if (!velocity_force.empty() && r.velocity_force > 0.0)
    distribute(r.velocity_force * pen.normal, pen.t, p, e0, e1, velocity_force);
  return r;
}

}  // namespace vorodg
