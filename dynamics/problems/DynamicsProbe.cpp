#include "dynamics/problems/DynamicsProbe.hpp"

#include <algorithm>
#include <cmath>

#include "core/io/StateArchive.hpp"

namespace vorodg {

DynamicsProbe::DynamicsProbe(const ExplicitParameters& physics, const DynamicsProblem& problem,
                             const BodiesMesh& bodies, const CentralDifference& run,
                             int output_every)
    : physics_(physics), bodies_(bodies), run_(run), start_(run.record()), frames_(bodies.mesh) {
  const Eigen::VectorXd& mass = run.node_masses();
  total_mass_ = mass.sum();
  for (int i = 0; i < mass.size(); ++i)
    momentum_scale_ += mass[i] * run.velocity().segment<2>(2 * i).norm();
  // Only what no wall, prescribed velocity, gravity or damping acts on keeps its momentum.
  conserves_momentum_ = !external_momentum(physics, problem);
  conserves_angular_momentum_ = conserves_momentum_ && problem.measures_angular_momentum();
  if (physics.corotational) m_.max_rotation = NAN;
  if (conserves_momentum_) m_.momentum_drift = 0.0;
  if (conserves_angular_momentum_) m_.angular_momentum_drift = 0.0;
  if (physics.wall) {
    const Point n = physics.wall->normal;
    m_.impact_velocity = -start_.momentum.dot(n) / total_mass_;
    m_.rebound_estimate = m_.impact_velocity;
    m_.contact_time_estimate = 2.0 * extent(physics.bodies[0].domain, n) / physics.bar_speed();
    m_.peak_wall_force = 0.0;
    m_.wall_impulse = 0.0;
    m_.penalty_ratio = bodies.h_avg / (2.0 * physics.dilatational_speed() * run.dt());
    m_.peak_wall_force_window = 0.0;
    const double transit = bodies.h_avg / physics.dilatational_speed();
    wall_window_.assign(std::max<long>(1, std::lround(transit / run.dt())), 0.0);
    m_.peak_wall_force_estimate = physics.density * physics.bar_speed() * m_.impact_velocity *
                                  extent(physics.bodies[0].domain, Point(-n.y(), n.x()));
  }
  problem_ = problem.probe(physics, bodies, run, output_every, m_);
}

void DynamicsProbe::observe_contact() {
  const ContactForces* contact = run_.contact();
  if (!contact) return;
  const ContactReport& a = contact->surface_report();
  const ContactReport& b = contact->plane_report();
  m_.max_penetration = std::max({m_.max_penetration, a.max_depth, b.max_depth});
  m_.max_penetration_over_h = m_.max_penetration / bodies_.h_avg;
  m_.tunnelled_contacts += a.new_tunnels;
  m_.late_contacts += a.new_late;
  if (physics_.wall) {
    m_.peak_wall_force = std::max(m_.peak_wall_force, contact->plane_force().norm());
    const double f = contact->plane_force().dot(physics_.wall->normal);
    if (observed_) m_.wall_impulse += 0.5 * run_.dt() * (last_wall_force_ + f);
    window_sum_ += f - wall_window_[window_next_];
    wall_window_[window_next_] = f;
    window_next_ = (window_next_ + 1) % wall_window_.size();
    m_.peak_wall_force_window =
        std::max(m_.peak_wall_force_window, window_sum_ / static_cast<double>(wall_window_.size()));
    last_wall_force_ = f;
    observed_ = true;
  }
  in_contact_ = a.contacts + b.contacts > 0;
  if (!in_contact_) return;
  if (std::isnan(m_.contact_start)) m_.contact_start = run_.time();
  m_.contact_end = run_.time();
  ++m_.contact_steps;
}

void DynamicsProbe::observe_rotation() {
  if (physics_.corotational) return;  // the cells' frames turn with them: no limit to watch
  const double largest = frames_.largest_mean_rotation(run_.dofs(), run_.displacement());
  m_.max_rotation = std::max(m_.max_rotation, largest);
  if (std::isnan(m_.large_rotation_time) && largest > kLargeRotation)
    m_.large_rotation_time = run_.time();
}

void DynamicsProbe::observe() {
  const StepRecord& r = run_.record();
  const double input = r.input_energy();
  const double error = input > 0.0 ? std::abs(r.balance() - r.initial_balance) / input : 0.0;
  m_.energy_balance_error = error;
  m_.max_energy_balance_error = std::max(m_.max_energy_balance_error, error);
  if (conserves_momentum_)
    m_.momentum_drift =
        std::max(m_.momentum_drift, (r.momentum - start_.momentum).norm() /
                                        (momentum_scale_ > 0.0 ? momentum_scale_ : 1.0));
  if (conserves_angular_momentum_)
    m_.angular_momentum_drift = std::max(m_.angular_momentum_drift,
                                         std::abs(r.angular_momentum - start_.angular_momentum) /
                                             std::max(std::abs(start_.angular_momentum), 1e-300));
  if (problem_) problem_->observe(m_);
  observe_contact();
}

void DynamicsProbe::watch_cracks(const CohesiveForces& cohesive) {
  if (problem_) problem_->watch_cracks(cohesive);
}

void DynamicsProbe::write(const std::filesystem::path& out, const std::string& run) const {
  if (problem_) problem_->write(out, run);
}

const DynamicsMeasures& DynamicsProbe::finish() {
  m_.contact_ended = !in_contact_;
  // A contact from the step it was first seen to the last: within a step of its duration.
  if (m_.contact_steps > 0) m_.contact_time = m_.contact_end - m_.contact_start + run_.dt();
  if (physics_.wall)
    m_.rebound_velocity = run_.record().momentum.dot(physics_.wall->normal) / total_mass_;
  if (const ContactForces* contact = run_.contact()) {
    m_.contact_friction_dissipated = contact->friction_dissipated();
    m_.contact_velocity_dissipated = contact->velocity_penalty_dissipated();
  }
  m_.bulk_viscosity_dissipated = run_.record().bulk_viscosity_dissipation;
  return m_;
}

void DynamicsProbe::archive(StateArchive& a) {
  a.value("probe.measures", m_);
  a.value("probe.start", start_);
  a.value("probe.in_contact", in_contact_);
  a.value("probe.last_wall_force", last_wall_force_);
  a.vector("probe.wall_window", wall_window_);
  a.value("probe.window_next", window_next_);
  a.value("probe.window_sum", window_sum_);
  a.value("probe.observed", observed_);
  if (problem_) problem_->archive(a);
}

}  // namespace vorodg
