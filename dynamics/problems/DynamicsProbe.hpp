#pragma once
// What a dynamics run measures, step by step, from the integrator's records and the contact
// reports: the drift of the energy balance and of the momenta, the contact's depth, duration and
// rebound, each set beside its theory (the 1D elastic bar: rebound speed = impact speed, contact
// time = 2 L / c_bar), and what the problem measures of its own (a wave's arrival).
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "dynamics/BodiesMesh.hpp"
#include "dynamics/CentralDifference.hpp"
#include "dynamics/CorotationalFrames.hpp"
#include "dynamics/ExplicitParameters.hpp"
#include "dynamics/problems/DynamicsProblem.hpp"

namespace vorodg {

class StateArchive;

struct DynamicsMeasures {
  double energy_balance_error = 0.0;      // at the end, of the input energy
  double max_energy_balance_error = 0.0;  // over every step
  double momentum_drift = NAN;            // free bodies: max |P - P0| / sum_i m_i |v_i(0)|
  double angular_momentum_drift = NAN;    // free-body: max |L - L0| / |L0|
  // wave-bar
  double arrival_time = NAN, arrival_theory = NAN, wave_speed = NAN, wave_speed_theory = NAN;
  double wave_speed_error = NAN;  // measured / theory - 1
  // contact (wall or bodies)
  double max_penetration = 0.0, max_penetration_over_h = 0.0;
  double contact_start = NAN, contact_end = NAN;  // first and last step in contact
  double contact_time = NAN, contact_time_estimate = NAN;
  int contact_steps = 0;
  double tunnelled_contacts = 0.0;  // vertices found first deep inside a cell, left alone
  double late_contacts = 0.0;       // found first deeper than a step goes: act beyond that
  bool contact_ended = true;        // no contact at the last step
  // wall: normal speeds of the centre of mass, towards the wall at t = 0 and away at the end
  double impact_velocity = NAN, rebound_velocity = NAN, rebound_estimate = NAN;
  // the largest net force of the wall on the bodies (per unit thickness), beside the 1D bar's
  // rho c_bar v_n times the body's width across the normal
  double peak_wall_force = NAN, peak_wall_force_estimate = NAN;
  // the largest of the wall's normal force averaged over a cell's transit time h_avg / c (c
  // dilatational): what converges with the step where the peak itself does not (an exact
  // plane stops a vertex within one step, with a force m v / dt)
  double peak_wall_force_window = NAN;
  // the wall's impulse on the bodies along its normal (per unit thickness, N s/m): its force
  // summed over the steps as the integrator applies it (the trapezoid rule of velocity Verlet),
  // so that with nothing else acting it is the change of the bodies' normal momentum; the 1D
  // elastic bar's is 2 M v_n, a plastic impact's M v_n
  double wall_impulse = NAN;
  // the report's plastic velocity penalty k_v = m / dt at this step and mesh: R = h / (2 c dt)
  // (c dilatational, h = h_avg), the 1D ratio of a surface node's mass to the impedance the step
  // gives it; that penalty passes R / (1 + R) of an impact's stress rho c v (docs/contact.md).
  // Recorded for every run with a wall, whatever law it uses.
  double penalty_ratio = NAN;
  // column-impact: the first time a vertex of the column's rear (upper) half touches the plane
  double rear_strike_time = NAN;
  // three-point-bend: the largest load (N: the load point's reaction times the thickness), the
  // load point's displacement and the crack mouth opening then (m), and the kinetic energy over
  // the work put in then and at the end (how far from quasi-static the run was)
  double peak_load = NAN, peak_load_displacement = NAN, peak_load_cmod = NAN;
  double kinetic_over_work_at_peak = NAN, kinetic_over_work_end = NAN;
  // the slip work of Coulomb friction: between surfaces and on the wall, and on crack faces
  double contact_friction_dissipated = NAN, face_friction_dissipated = NAN;
  // what contact's velocity penalty (damping or plastic) and the cells' bulk viscosity took
  double contact_velocity_dissipated = NAN, bulk_viscosity_dissipated = NAN;
  // fragmentation (Fragmentation, FragmentRecord): fragments are bounded by fully broken edges
  double fragments = NAN, max_fragment_mass_fraction = NAN, dissipated_energy = NAN;
  double single_cell_mass_fraction = NAN;  // the mass in fragments of one cell, of the total
  // The largest fragment's turn at the end, rad: the polar angle of its mass-weighted mean
  // deformation gradient (exact for a rigid turn of any size, whatever the kinematics)
  double main_body_rotation = NAN;
  double cracked_edges = NAN, broken_edges = NAN;
  // where the broken edges are, as fractions of them (runs with a wall, CrackLocations): within
  // a body width of the impact point, in the middle third of the body's length, elsewhere
  double broken_near_impact = NAN, broken_mid_length = NAN, broken_elsewhere = NAN;
  double released_edges = NAN;  // broken faces let go to surface contact (CohesiveForces)
  // interfaces coupled from the start (interfaces: dg): how many were activated, and the work at
  // activation (the law's starting energy less the coupling energy removed), of the input energy
  double activated_interfaces = NAN, activation_work = NAN;
  // wall seconds in the insertion check and in the rebuilds after cracks (DynamicFracture)
  double check_seconds = NAN, rebuild_seconds = NAN;
  double coupling_seconds = NAN;         // in the interface coupling's forces (interfaces: dg)
  double law_balance_error = NAN;        // max over steps, with the law's closed-form energies
  double law_balance_breach_time = NAN;  // first time it passed kLawBalanceLimit (NaN: never)
  // small rotations (CorotationalFrames::mean_rotation), sampled at the output steps; NaN under
  // corotational kinematics
  double max_rotation = 0.0;         // the largest cell's mean rotation, rad
  double large_rotation_time = NAN;  // first output time at which it passed kLargeRotation
};

/// A cell rotated further than this (rad) is drawn, and meets contact, stretched by more than
/// theta^2 / 2 = 0.5 %: past it the small-strain model no longer describes where fragments are.
constexpr double kLargeRotation = 0.1;

class DynamicsProbe {
 public:
  /// `run` must be initialized; it, the parameters, the problem and the mesh outlive the probe.
  /// Rotations are sampled (and a problem's curves drawn) every `output_every` steps.
  DynamicsProbe(const ExplicitParameters& physics, const DynamicsProblem& problem,
                const BodiesMesh& bodies, const CentralDifference& run, int output_every);

  /// After every step: books the step's record and contact reports.
  void observe();
  /// At the output steps: the cells' rotations against kLargeRotation.
  void observe_rotation();
  /// After the last step: the rebound, the contact time.
  const DynamicsMeasures& finish();
  /// Fragmentation: the run's cohesive faces, for the problem's measures of their energies.
  void watch_cracks(const CohesiveForces& cohesive);
  /// After the run: the problem's own per-run files under `out` (ProblemProbe::write).
  void write(const std::filesystem::path& out, const std::string& run) const;
  const DynamicsMeasures& measures() const { return m_; }

  /// Saves or loads the measures so far and what the next observation reads (a checkpoint).
  void archive(StateArchive& a);

 private:
  void observe_contact();

  const ExplicitParameters& physics_;
  const BodiesMesh& bodies_;
  const CentralDifference& run_;
  DynamicsMeasures m_;
  StepRecord start_;
  double momentum_scale_ = 0.0, total_mass_ = 0.0;
  bool conserves_momentum_ = false, conserves_angular_momentum_ = false;
  CorotationalFrames frames_;              // for the cells' small-strain rotation
  std::unique_ptr<ProblemProbe> problem_;  // the problem's own measures (may be none)
  bool in_contact_ = false;
  double last_wall_force_ = 0.0;  // along the normal, at the last step observed
  // The wall's normal force over the last steps of a cell transit time, and their sum
  std::vector<double> wall_window_;
  std::size_t window_next_ = 0;
  double window_sum_ = 0.0;
  bool observed_ = false;  // a step has been observed (the impulse's first end)
};

}  // namespace vorodg
