#include "verification/kinds/dynamics/DynamicsProbe.hpp"

#include <algorithm>

namespace vorodg {
namespace {

/// The extent of a rectangle along a unit direction: the length a 1D wave crosses.
double extent(const Rectangle& r, const Point& direction) {
  return std::abs(direction.x()) * r.width() + std::abs(direction.y()) * r.height();
}

}  // namespace

DynamicsProbe::DynamicsProbe(const DynamicsScene& scene, const BodiesMesh& bodies,
                             const CentralDifference& run)
    : scene_(scene), bodies_(bodies), run_(run), start_(run.record()), frames_(bodies.mesh) {
  const Eigen::VectorXd& mass = run.node_masses();
  total_mass_ = mass.sum();
  for (int i = 0; i < mass.size(); ++i)
    momentum_scale_ += mass[i] * run.velocity().segment<2>(2 * i).norm();
  // Only what no wall, prescribed velocity, gravity or damping acts on keeps its momentum.
  conserves_momentum_ = !scene.external_momentum();
  if (scene.corotational) m_.max_rotation = NAN;
  if (conserves_momentum_) m_.momentum_drift = 0.0;
  if (conserves_momentum_ && scene.problem == DynamicsProblem::free_body)
    m_.angular_momentum_drift = 0.0;
  if (scene.problem == DynamicsProblem::wave_bar) {
    const PolygonMesh& mesh = bodies.mesh;
    std::vector<char> on(mesh.num_vertices(), 0);
    for (const MeshEdge& e : mesh.edges())
      if (e.side == Side::right) on[e.v0] = on[e.v1] = 1;
    for (int v = 0; v < mesh.num_vertices(); ++v)
      if (on[v])
        for (int node : run.dofs().vertex_nodes(v)) far_nodes_.push_back(node);
    const double length = scene.bodies[0].domain.width();
    m_.wave_speed_theory = scene.wave_speed();
    m_.arrival_theory = length / m_.wave_speed_theory;
  }
  if (scene.wall) {
    const Point n = scene.wall->normal;
    m_.impact_velocity = -start_.momentum.dot(n) / total_mass_;
    m_.rebound_estimate = m_.impact_velocity;
    m_.contact_time_estimate = 2.0 * extent(scene.bodies[0].domain, n) / scene.bar_speed();
  } else if (scene.problem == DynamicsProblem::two_blocks) {
    const Point relative = scene.bodies[0].velocity - scene.bodies[1].velocity;
    const Point d = relative.norm() > 0.0 ? Point(relative.normalized()) : Point(1.0, 0.0);
    const double shorter =
        std::min(extent(scene.bodies[0].domain, d), extent(scene.bodies[1].domain, d));
    m_.contact_time_estimate = 2.0 * shorter / scene.bar_speed();
  }
}

double DynamicsProbe::far_end_velocity() const {
  double p = 0.0, m = 0.0;
  for (int node : far_nodes_) {
    p += run_.node_masses()[node] * run_.velocity()[2 * node];
    m += run_.node_masses()[node];
  }
  return p / m;
}

void DynamicsProbe::observe_wave() {
  const double amplitude = scene_.pulse_amplitude, now = far_end_velocity();
  // At the free far end the particle velocity doubles: the incident amplitude is reached at half
  // the doubled plateau. The input reaches half its amplitude a half rise (duration / 6) after
  // t = 0, so that is taken off to time the mid-rise's travel.
  if (std::isnan(m_.arrival_time) && now / amplitude >= 1.0) {
    const double t = run_.time() - run_.dt() * (now - amplitude) / (now - previous_far_);
    m_.arrival_time = t - scene_.pulse_duration / 6.0;
    const double length = scene_.bodies[0].domain.width();
    m_.wave_speed = length / m_.arrival_time;
    m_.wave_speed_error = m_.wave_speed / m_.wave_speed_theory - 1.0;
  }
  previous_far_ = now;
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
  in_contact_ = a.contacts + b.contacts > 0;
  if (!in_contact_) return;
  if (std::isnan(m_.contact_start)) m_.contact_start = run_.time();
  m_.contact_end = run_.time();
  ++m_.contact_steps;
}

void DynamicsProbe::observe_rotation() {
  if (scene_.corotational) return;  // the cells' frames turn with them: no limit to watch
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
  if (conserves_momentum_ && scene_.problem == DynamicsProblem::free_body)
    m_.angular_momentum_drift = std::max(m_.angular_momentum_drift,
                                         std::abs(r.angular_momentum - start_.angular_momentum) /
                                             std::max(std::abs(start_.angular_momentum), 1e-300));
  if (scene_.problem == DynamicsProblem::wave_bar) observe_wave();
  observe_contact();
}

const DynamicsMeasures& DynamicsProbe::finish() {
  m_.contact_ended = !in_contact_;
  // A contact from the step it was first seen to the last: within a step of its duration.
  if (m_.contact_steps > 0) m_.contact_time = m_.contact_end - m_.contact_start + run_.dt();
  if (scene_.wall)
    m_.rebound_velocity = run_.record().momentum.dot(scene_.wall->normal) / total_mass_;
  return m_;
}

}  // namespace vorodg
