#pragma once
// What CentralDifference books after every step: energies, work, momenta (per unit thickness).
//
// The energy balance of central differences. With the half-step velocities v_{n+-1/2} that
// move the displacements, the exact discrete identity is
//     K*_{n+1} - K*_n = 1/2 (u_{n+1} - u_n).(F_n + F_{n+1}),   K*_n = 1/2 v_{n-1/2}.M v_{n+1/2}
// for the total nodal force F = M a (applied, contact, cohesive, internal, damping and reaction
// forces). Every work below is that trapezoid of its own force, and for linear elasticity the
// internal part is exactly the change of 1/2 u.K u. So kinetic_leapfrog + elastic +
// damping_dissipation + bulk_viscosity_dissipation - external_work - reaction_work - contact_work -
// cohesive_work is constant to round-off. The usual kinetic energy 1/2 v.M v at whole steps differs
// from K* by dt^2/8 a.M a: an oscillation of relative size about (omega dt)^2 / 4 for the
// frequencies carrying the energy, not a drift; balance_integer() shows it.
#include <Eigen/Core>
#include <cmath>

namespace vorodg {

struct StepRecord {
  long step = 0;
  double time = 0.0;
  double kinetic = 0.0;           // 1/2 v_n.M v_n
  double kinetic_leapfrog = 0.0;  // 1/2 v_{n-1/2}.M v_{n+1/2} = kinetic - dt^2/8 a.M a
  double elastic = 0.0;           // 1/2 u.K u, the sum of the cell energies
  double external_work = 0.0;     // body and external forces, cumulative
  double reaction_work = 0.0;     // reactions at prescribed velocities, cumulative
  double contact_work = 0.0;      // contact forces (surfaces and planes), cumulative (ContactWork)
  double cohesive_work = 0.0;     // cohesive tractions on cracks, cumulative (CohesiveForces)
  double damping_dissipation = 0.0;
  double bulk_viscosity_dissipation = 0.0;  // BulkViscosity's work with its sign turned, cumulative
  double remap_energy = 0.0;                // energy changes at node splits or merges, cumulative
  double activation_energy = 0.0;  // energy changes where coupled interfaces became cracks, cum.
  Eigen::Vector2d momentum = Eigen::Vector2d::Zero();  // sum M v
  double angular_momentum = 0.0;                       // sum (X + u) x M v about the origin
  // The balances at step 0, for the drift of either.
  double initial_balance = 0.0;
  double initial_balance_integer = 0.0;

  /// Energy in the body plus what left it, minus what entered: constant to round-off.
  double balance() const {
    return kinetic_leapfrog + elastic + damping_dissipation + bulk_viscosity_dissipation -
           external_work - reaction_work - contact_work - cohesive_work - remap_energy -
           activation_energy;
  }
  /// The same with 1/2 v.M v (oscillates by dt^2/8 a.M a).
  double balance_integer() const { return balance() + kinetic - kinetic_leapfrog; }
  /// Work put in (external, reaction, contact) plus the initial energy: the scale for relative
  /// drifts.
  double input_energy() const;
};

inline double StepRecord::input_energy() const {
  return std::abs(external_work) + std::abs(reaction_work) + std::abs(contact_work) +
         std::abs(initial_balance_integer);
}

}  // namespace vorodg
