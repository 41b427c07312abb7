#pragma once
// The penalty law of contact (after Heinstein, Mello, Attaway and Laursen, "Contact-impact
// modeling in explicit transient dynamics", CMAME 2000): a penetrating vertex gets the force
//   f = (k_d d + k_v <-v_n>) n,   <x> = max(x, 0),
// with d the depth, n the unit normal out of what it penetrates and v_n the normal component of
// its velocity relative to the point q it is pushed towards. The displacement part is a spring;
// the velocity part damps approach only, so it never pulls surfaces together.
//
// **Choice: the stiffness is scaled by mass and step,** k_d = alpha m / dt^2, where m is the
// reduced mass of the vertex and the target, m = m_p m_e / (m_p + m_e), and m_e is the smaller
// end mass of the target edge (infinite for a rigid plane). The contact alone is then a spring on
// m with omega^2 dt^2 = alpha, whatever q's position t on the edge: the target side adds
// ((1 - t)^2 / m_0 + t^2 / m_1) <= 1 / m_e to 1 / m. So contact never limits the stable step,
// whatever the material and the mesh: central differences are stable for omega dt < 2, and with
// the elements' own omega_e dt = 2 s at a step fraction s the sum stays stable while
// alpha < 4 (1 - s^2), i.e. 0.76 at s = 0.9. alpha = 1 removes a penetration in one step, like
// a kinematic constraint; larger values are refused, because the discrete spring then gains
// energy at impacts (at alpha = 3.5 a mass bounces off a rigid plane 45% faster than it came, on
// average over the entry phases, measured). The default alpha = 0.1 leaves room for a vertex
// pressed by a few targets at once (their stiffnesses add) and keeps an elastic impact's rebound
// speed within 0.5% of the impact speed, whatever the phase at which the vertex enters (measured;
// 3.5% at alpha = 0.3). The price is softness: a vertex arriving at speed v penetrates
// v dt / sqrt(alpha), ~3 steps' motion at 0.1, which is small next to a cell because a stable
// step moves a vertex far less than a cell. A fixed stiffness k_d can be given instead, in force
// per unit thickness per unit depth (units of E: e.g. kappa E).
//
// The damping is a fraction zeta of the critical damping of that spring, k_v = 2 zeta sqrt(k_d m),
// with the half-step velocities of central differences (k_v dt / m = 2 zeta sqrt(alpha) < 2).
// **Choice: zeta = 0 by default,** so that impacts are elastic and the energy balance shows only
// the integrator's error; zeta = 0.1 calms contact ringing and gives a rebound of about 0.85 of
// the impact speed (damping acts on approach only). The report's own choice is selectable:
// `plastic`, k_v = m / dt, removes a pair's approach velocity in one step (a plastic impact of
// the pair; a body still rebounds by its own elastic waves).
//
// Stability of the plastic penalty: k_v = m / dt on the half-step velocity removes a contacting
// vertex's own velocity each step, so its update for a mode of frequency omega of the body
// becomes u_{n+2} = (1 - omega^2 dt^2) u_{n+1}: stable only while omega dt < sqrt(2), not 2
// (measured: a column set down on a level plane with it blew up within 0.5 s at 0.9 of the
// critical step). The step is then cut by step_factor() = 1 / sqrt(2) (ExplicitSimulation).
//
// Energy: with k_d constant along a contact, the spring force is the gradient of k_d d^2 / 2
// (PolygonPenetration), and the damping dissipates k_v <-v_n>^2 >= 0 per unit time
// (ContactReport). That rate is only a first-order estimate of what the velocity force takes
// over a step (for the plastic penalty's first impulse on a free pair it is twice the kinetic
// energy removed, under a sustained push about right), so ContactForces books the velocity
// force's own trapezoid work beside the total (`velocity_force` of apply and Response). The exact
// account is the work of the contact forces (ContactWork). When the closest edge of a vertex
// changes to one with a different end mass, k_d jumps and the potential with it (never with a
// fixed stiffness).
#include <cmath>
#include <span>

#include "dynamics/contact/PairState.hpp"
#include "dynamics/contact/PolygonPenetration.hpp"

namespace vorodg {

struct PenaltyParameters {
  /// k_d = alpha m / dt^2 (m the contact's reduced mass), in (0, 1].
  double alpha = 0.1;
  /// zeta in [0, 1]: k_v = 2 zeta sqrt(k_d m), a fraction of the critical damping.
  double damping_ratio = 0.0;
  /// > 0: a fixed k_d instead of alpha m / dt^2 (force per unit thickness per unit depth).
  double stiffness = 0.0;
  /// The report's velocity penalty, which makes an impact plastic: k_v = m / dt, so that the
  /// impulse over one step removes the approach velocity of the pair (k_v dt / m = 1 < 2:
  /// stable). Replaces damping_ratio's k_v.
  bool plastic = false;
};

class PenaltyContact {
 public:
  /// Throws InputError naming the parameter out of range.
  explicit PenaltyContact(const PenaltyParameters& parameters = {});

  const PenaltyParameters& parameters() const { return p_; }
  bool needs_mass() const { return p_.stiffness == 0.0 || p_.damping_ratio > 0.0 || p_.plastic; }
  bool needs_velocity() const { return p_.damping_ratio > 0.0 || p_.plastic; }
  /// What the law leaves of the system's critical step 2 / omega_max: 1, or 1 / sqrt(2) with the
  /// plastic velocity penalty (see Stability above).
  double step_factor() const { return p_.plastic ? 1.0 / std::sqrt(2.0) : 1.0; }
  /// Throws InputError if the state lacks a field the law needs (mass, velocity, dt > 0).
  void check(const PairState& state, const char* what) const;

  /// Reduced mass of a vertex of mass m_p against a target of mass m_e (infinite: rigid).
  static double reduced_mass(double m_p, double m_e);
  double stiffness(double mass, double dt) const;
  double damping(double stiffness, double mass) const;

  struct Response {
    double force = 0.0;  // magnitude along n
    double potential = 0.0;
    double dissipation_power = 0.0;
    double stiffness = 0.0;       // k_d, also the stick spring of friction (ContactFriction)
    double velocity_force = 0.0;  // the velocity penalty's part of `force`, k_v <-v_n>
  };
  /// The law for depth d > 0, approach rate -v_n (> 0 while the depth grows), contact mass m
  /// and step dt.
  Response respond(double depth, double approach_rate, double mass, double dt) const;

  /// The velocity of pair `p` relative to the point q of its penetration `pen` into the edge of
  /// pairs `e0`, `e1`; zero when the state has no velocities.
  static Point relative_velocity(const Penetration& pen, int p, int e0, int e1,
                                 const PairState& state);
  /// -v_n: how fast pair `p` approaches the point q of its penetration `pen` into the edge of
  /// pairs `e0`, `e1` (> 0 while the depth grows); 0 when the state has no velocities.
  static double approach_rate(const Penetration& pen, int p, int e0, int e1,
                              const PairState& state);

  /// Applies one vertex-to-edge penetration: F n to pair `p`, and -F n split (1 - t, t) over the
  /// pairs `e0`, `e1` at the ends of the penetrated edge. Adds to `force` (one entry per pair),
  /// and the velocity penalty's part alone to `velocity_force` if it is not empty.
  Response apply(const Penetration& pen, int p, int e0, int e1, const PairState& state,
                 std::span<Point> force, std::span<Point> velocity_force = {}) const;
  /// Adds `f` to pair `p` and -f split (1 - t, t) over the pairs `e0`, `e1` of the edge.
  static void distribute(const Point& f, double t, int p, int e0, int e1, std::span<Point> force);

 private:
  PenaltyParameters p_;
};

}  // namespace vorodg
