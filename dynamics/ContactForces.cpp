#include "dynamics/ContactForces.hpp"

#include "core/io/StateArchive.hpp"
#include "dynamics/contact/ContactLaws.hpp"
#include "dynamics/contact/PolygonPenetration.hpp"

#include <algorithm>
#include <string>

#include "core/util/Errors.hpp"

namespace vorodg {

ContactForces::ContactForces(const PolygonMesh& mesh, const PenaltyContact& law, bool surfaces,
                             const ContactFriction& friction, const std::string& surface_law)
    : mesh_(mesh), law_(law), surfaces_(surfaces), surface_(mesh) {
  if (surfaces)
    add_law(
        make_contact_law(surface_law, {.penalty = law,
                                       .friction = friction,
                                       .grid_spacing = mesh.h_avg() > 0.0 ? mesh.h_avg() : 1.0}));
  reference_.reserve(mesh.offsets().back());
  for (int v : mesh.cell_vertex_list()) reference_.push_back(mesh.vertex(v));
  const std::size_t pairs = reference_.size();
  for (auto* buffer : {&position_, &velocity_, &force_, &plane_pair_force_})
    buffer->assign(pairs, Point::Zero());
  impulse_force_.assign(pairs, Point::Zero());
  friction_force_.assign(pairs, Point::Zero());
  if (law.needs_velocity()) velocity_force_.assign(pairs, Point::Zero());
}

void ContactForces::add_law(std::unique_ptr<ContactLaw> law) {
  obstacles_ = obstacles_ || law->external();
  kinematic_ = kinematic_ || law->kinematic();
  laws_.push_back(std::move(law));
}

void ContactForces::add_plane(const Point& point, const Point& normal,
                              const ContactFriction& friction) {
  add_law(make_contact_law(
      "penalty-plane", {.penalty = law_, .friction = friction, .point = point, .normal = normal}));
}

void ContactForces::bind(const SplitDofMap& dofs, const Eigen::VectorXd& node_masses) {
  if (node_masses.size() != dofs.num_nodes())
    throw InputError("contact: " + std::to_string(node_masses.size()) +
                     " node masses: expected one per node, " + std::to_string(dofs.num_nodes()));
  node_.resize(reference_.size());
  mass_.resize(reference_.size());
  size_nodes(dofs.num_nodes());
  for (int i = 0; i < dofs.num_nodes(); ++i) bind_node(dofs, node_masses, i);
  num_dofs_ = dofs.num_dofs();
}

void ContactForces::size_nodes(int nodes) {
  for (auto* buffer : {&node_velocity_, &normal_impulse_, &friction_impulse_})
    buffer->resize(nodes, Point::Zero());
  inverse_mass_.resize(nodes, 0.0);
  node_inverse_mass_.resize(nodes, 0.0);
}

void ContactForces::rebind(const SplitDofMap& dofs, const Eigen::VectorXd& node_masses,
                           std::span<const int> nodes) {
  if (node_masses.size() != dofs.num_nodes())
    throw InputError("contact: " + std::to_string(node_masses.size()) +
                     " node masses: expected one per node, " + std::to_string(dofs.num_nodes()));
  size_nodes(dofs.num_nodes());
  for (int i : nodes) bind_node(dofs, node_masses, i);
  num_dofs_ = dofs.num_dofs();
}

void ContactForces::bind_node(const SplitDofMap& dofs, const Eigen::VectorXd& node_masses, int i) {
  node_inverse_mass_[i] = 1.0 / node_masses[i];
  for (int p : dofs.node_pairs(i)) {
    node_[p] = i;
    mass_[p] = node_masses[i];
  }
}

void ContactForces::restart() {
  for (SegmentedWork* w : {&work_, &velocity_work_, &impulse_work_, &friction_work_}) w->restart();
  repeat_ = true;
}

void ContactForces::gather_state(const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
  if (num_dofs_ < 0) throw InputError("contact: evaluate() before bind()");
  if (u.size() != num_dofs_ || v.size() != num_dofs_)
    throw InputError("contact: " + std::to_string(u.size()) + " displacements and " +
                     std::to_string(v.size()) + " velocities: expected " +
                     std::to_string(num_dofs_) + " each");
  // Only the surface cells' pairs: no other pair is read (the set only grows, so a pair read
  // once is read at every later step).
  const auto& o = mesh_.offsets();
  for (int c : surface_.cells())
    for (int p = o[c]; p < o[c + 1]; ++p) {
      const int n = node_[p];
      position_[p] = reference_[p] + Point(u[2 * n], u[2 * n + 1]);
      velocity_[p] = Point(v[2 * n], v[2 * n + 1]);
    }
}

void ContactForces::clear_forces() {
  for (int p : support_) {
    force_[p] = Point::Zero();
    plane_pair_force_[p] = Point::Zero();
    if (!velocity_force_.empty()) velocity_force_[p] = Point::Zero();
  }
}

void ContactForces::collect_support() {
  // What the laws pushed, ascending and once each: a fixed order for every sum below, and no pass
  // over the pairs contact left alone.
  support_.clear();
  for (const auto& law : laws_)
    support_.insert(support_.end(), law->touched().begin(), law->touched().end());
  std::sort(support_.begin(), support_.end());
  support_.erase(std::unique(support_.begin(), support_.end()), support_.end());
  if (!obstacles_) return;
  for (int p : support_) {
    plane_force_ += plane_pair_force_[p];
    force_[p] += plane_pair_force_[p];
  }
}

void ContactForces::evaluate(const Eigen::VectorXd& u, const Eigen::VectorXd& v, double dt,
                             Eigen::VectorXd& f) {
  gather_state(u, v);
  evaluated_ = true;
  clear_forces();
  const PairState state{position_, velocity_, mass_, node_, dt, repeat_};
  dt_ = dt;
  repeat_ = false;
  // The obstacles into their own buffer first: their net force is the wall's reaction, reported.
  surface_report_ = ContactReport{};
  plane_report_ = ContactReport{};
  plane_force_.setZero();
  for (const auto& law : laws_) {
    if (law->external())
      plane_report_ += law->add_forces(surface_, state, plane_pair_force_, velocity_force_);
    else
      surface_report_ += law->add_forces(surface_, state, force_, velocity_force_);
  }
  collect_support();
  friction_dissipated_ += surface_report_.friction_dissipated + plane_report_.friction_dissipated;
  work_.add(force_, support_, velocity_, dt);
  if (!velocity_force_.empty()) velocity_work_.add(velocity_force_, support_, velocity_, dt);
  f.setZero(num_dofs_);
  for (int p : support_) {
    f[2 * node_[p]] += force_[p].x();
    f[2 * node_[p] + 1] += force_[p].y();
  }
}

void ContactForces::constrain(const Prediction& next, double beta, double inertia,
                              Eigen::VectorXd& f) {
  if (!kinematic_) return;
  if (!evaluated_) throw InputError("contact: constrain() before evaluate()");
  const std::size_t nodes = node_inverse_mass_.size();
  if (next.velocity.size() != nodes || next.held.size() != nodes)
    throw InputError("contact: a prediction of " + std::to_string(next.velocity.size()) +
                     " velocities and " + std::to_string(next.held.size()) +
                     " holds: expected one per node, " + std::to_string(nodes));
  std::copy(next.velocity.begin(), next.velocity.end(), node_velocity_.begin());
  for (std::size_t n = 0; n < nodes; ++n)
    inverse_mass_[n] = next.held[n] ? 0.0 : node_inverse_mass_[n];
  for (int p : impulse_support_) impulse_force_[p] = friction_force_[p] = Point::Zero();
  impulse_support_.clear();
  KinematicState state{position_,         node_, node_velocity_, inverse_mass_, normal_impulse_,
                       friction_impulse_, dt_};
  for (const auto& law : laws_) {
    if (!law->kinematic()) continue;
    const ContactReport r = law->constrain(surface_, state);
    (law->external() ? plane_report_ : surface_report_) += r;
    collect_impulses(*law, inertia / (beta * dt_), f);
  }
  std::sort(impulse_support_.begin(), impulse_support_.end());
  impulse_support_.erase(std::unique(impulse_support_.begin(), impulse_support_.end()),
                         impulse_support_.end());
  impulse_work_.add(impulse_force_, impulse_support_, velocity_, dt_);
  friction_work_.add(friction_force_, impulse_support_, velocity_, dt_);
  // The pairs with a force are now both kinds': ascending and once each.
  const std::size_t pushed = support_.size();
  support_.insert(support_.end(), impulse_support_.begin(), impulse_support_.end());
  std::inplace_merge(support_.begin(), support_.begin() + pushed, support_.end());
  support_.erase(std::unique(support_.begin(), support_.end()), support_.end());
}

void ContactForces::collect_impulses(const ContactLaw& law, double to_force, Eigen::VectorXd& f) {
  for (int p : law.touched()) {
    const int n = node_[p];
    if (normal_impulse_[n] == Point::Zero() && friction_impulse_[n] == Point::Zero()) continue;
    const Point normal = to_force * normal_impulse_[n], friction = to_force * friction_impulse_[n];
    normal_impulse_[n] = friction_impulse_[n] = Point::Zero();  // each node's once
    if (impulse_force_[p] == Point::Zero() && friction_force_[p] == Point::Zero())
      impulse_support_.push_back(p);
    impulse_force_[p] += normal;
    friction_force_[p] += friction;
    const Point total = normal + friction;
    force_[p] += total;
    f[2 * n] += total.x();
    f[2 * n + 1] += total.y();
    if (!law.external()) continue;
    plane_pair_force_[p] += total;
    plane_force_ += total;
  }
}

bool ContactForces::overlapping(int a, int b) const {
  for (int c : {a, b})
    if (!surface_.contains(c))
      throw InputError("contact: overlapping(" + std::to_string(a) + ", " + std::to_string(b) +
                       "): cell " + std::to_string(c) +
                       " is not a surface cell, whose positions are not gathered");
  if (!evaluated_) return false;
  const auto& o = mesh_.offsets();
  const std::span<const Point> pa(position_.data() + o[a], position_.data() + o[a + 1]);
  const std::span<const Point> pb(position_.data() + o[b], position_.data() + o[b + 1]);
  for (const Point& p : pa)
    if (PolygonPenetration::inside(p, pb)) return true;
  for (const Point& p : pb)
    if (PolygonPenetration::inside(p, pa)) return true;
  return false;
}

void ContactForces::archive(StateArchive& a) {
  surface_.archive(a);
  for (const std::unique_ptr<ContactLaw>& law : laws_) law->archive(a);
  for (SegmentedWork* w : {&work_, &velocity_work_, &impulse_work_, &friction_work_}) w->archive(a);
  a.value("contact.friction_dissipated", friction_dissipated_);
  a.vector("contact.velocity_force", velocity_force_);
  for (auto [name, x] : {std::pair{"node_velocity", &node_velocity_},
                         {"normal_impulse", &normal_impulse_},
                         {"friction_impulse", &friction_impulse_},
                         {"impulse_force", &impulse_force_},
                         {"friction_force", &friction_force_},
                         {"position", &position_},
                         {"velocity", &velocity_},
                         {"force", &force_},
                         {"plane_pair_force", &plane_pair_force_}})
    a.vector(std::string("contact.") + name, *x);
  a.vector("contact.inverse_mass", inverse_mass_);
  a.vector("contact.impulse_support", impulse_support_);
  a.vector("contact.support", support_);
  a.value("contact.dt", dt_);
  a.value("contact.repeat", repeat_);
  a.value("contact.evaluated", evaluated_);
  a.value("contact.surface_report", surface_report_);
  a.value("contact.plane_report", plane_report_);
  a.value("contact.plane_force", plane_force_);
}

}  // namespace vorodg
