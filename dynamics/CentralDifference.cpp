#include "dynamics/CentralDifference.hpp"

#include <algorithm>
#include <string>

#include "core/io/StateArchive.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Stopwatch.hpp"

namespace vorodg {

CentralDifference::CentralDifference(const PolygonMesh& mesh, const LumpedMass& mass,
                                     InternalForce force, SplitDofMap dofs, double dt,
                                     const DynamicsOptions& options)
    : mesh_(mesh),
      mass_(mass),
      force_(std::move(force)),
      dofs_(std::move(dofs)),
      dt_(dt),
      options_(options) {
  require_parameter(dt > 0.0, "time step", dt, "> 0");
  require_parameter(options.damping >= 0.0, "damping", options.damping, ">= 0");
  bind();
}

void CentralDifference::bind() {
  mass_node_ = mass_.node_masses(dofs_);
  x0_.resize(dofs_.num_dofs());
  for (int c = 0; c < mesh_.num_cells(); ++c)
    for (int k = 0; k < mesh_.cell_size(c); ++k)
      x0_.segment<2>(2 * dofs_.node(c, k)) = mesh_.vertex(mesh_.cell_vertices(c)[k]);
  prescribed_.assign(dofs_.num_dofs(), -1);
  for (std::size_t j = 0; j < boundaries_.size(); ++j)
    for (int v : boundaries_[j].vertices)
      for (int node : dofs_.vertex_nodes(v)) {
        int& slot = prescribed_[2 * node + boundaries_[j].direction];
        if (slot >= 0)
          throw InputError("prescribed velocity: vertex " + std::to_string(v) + ", direction " +
                           std::to_string(boundaries_[j].direction) + ": prescribed twice");
        slot = static_cast<int>(j);
      }
  const int n = dofs_.num_dofs();
  for (Eigen::VectorXd* x : {&f_ext_, &f_ext_next_, &reaction_, &v_half_, &f_contact_,
                             &f_contact_next_, &f_bulk_, &f_bulk_next_})
    x->setZero(n);
  if (contact_) contact_->bind(dofs_, mass_node_);
  if (cohesive_) cohesive_->bind(dofs_);
}

void CentralDifference::set_contact(ContactForces& contact) {
  if (initialized_) throw InputError("contact: set after initialize()");
  contact_ = &contact;
  contact_->bind(dofs_, mass_node_);
}

void CentralDifference::set_bulk_viscosity(BulkViscosity& bulk) {
  if (initialized_) throw InputError("bulk viscosity: set after initialize()");
  bulk_ = &bulk;
}

void CentralDifference::bulk_forces(const Eigen::VectorXd& v, Eigen::VectorXd& f) {
  if (bulk_)
    bulk_->compute(dofs_, v, f, options_.threads, &u_);
  else
    f.setZero(dofs_.num_dofs());
}

void CentralDifference::set_cohesive(CohesiveForces& cohesive) {
  cohesive_ = &cohesive;
  cohesive_->bind(dofs_);
}

void CentralDifference::interface_forces(const Eigen::VectorXd& v, Eigen::VectorXd& f,
                                         bool openings_unchanged) {
  // Contact is always evaluated: its mass-scaled stiffness follows the node masses, which a
  // split changes.
  if (contact_)
    contact_->evaluate(u_, v, dt_, f);
  else
    f.setZero(dofs_.num_dofs());
  if (!cohesive_) return;
  if (openings_unchanged)
    cohesive_->reassemble(f);
  else
    cohesive_->evaluate(u_, f);
}

void CentralDifference::constrain_contact(const Eigen::VectorXd& w, double beta, double inertia,
                                          const Eigen::VectorXd& f_ext,
                                          const Eigen::VectorXd& f_bulk,
                                          Eigen::VectorXd& f_contact) {
  if (!contact_ || !contact_->kinematic()) return;
  const double c = options_.damping;
  const int nodes = dofs_.num_nodes();
  predicted_.resize(nodes);
  held_.resize(nodes);
  for (int node = 0; node < nodes; ++node) {
    const double m = mass_node_[node];
    held_[node] = prescribed_[2 * node] >= 0 || prescribed_[2 * node + 1] >= 0;
    for (int i = 2 * node; i < 2 * node + 2; ++i) {
      double applied = f_ext[i] + f_contact[i] - f_int_[i];
      if (bulk_) applied += f_bulk[i];
      predicted_[node][i - 2 * node] = w[i] + beta * dt_ * (applied - c * m * w[i]) / (m * inertia);
    }
  }
  contact_->constrain({predicted_, held_}, beta, inertia, f_contact);
}

void CentralDifference::add_velocity_boundary(VelocityBoundary bc) {
  if (initialized_) throw InputError("prescribed velocity: added after initialize()");
  if (bc.direction != 0 && bc.direction != 1)
    throw InputError("prescribed velocity: direction " + std::to_string(bc.direction) +
                     ": expected 0 (x) or 1 (y)");
  if (!bc.velocity) throw InputError("prescribed velocity: no velocity function given");
  for (int v : bc.vertices)
    if (v < 0 || v >= mesh_.num_vertices())
      throw InputError("prescribed velocity: vertex " + std::to_string(v) + ": expected 0 .. " +
                       std::to_string(mesh_.num_vertices() - 1));
  boundaries_.push_back(std::move(bc));
  bind();
}

void CentralDifference::boundary_values(double t, std::vector<double>& out) const {
  out.resize(boundaries_.size());
  for (std::size_t j = 0; j < boundaries_.size(); ++j) out[j] = boundaries_[j].velocity(t);
}

void CentralDifference::external_forces(double t, Eigen::VectorXd& f) {
  f.setZero(dofs_.num_dofs());
  if (body_force_) {
    const Eigen::Vector2d b = body_force_(t);
    for (int i = 0; i < dofs_.num_nodes(); ++i) f.segment<2>(2 * i) = mass_node_[i] * b;
  }
  if (external_force_) external_force_(t, u_, f);
}

void CentralDifference::initialize(const Eigen::VectorXd& u0, const Eigen::VectorXd& v0) {
  if (u0.size() != dofs_.num_dofs() || v0.size() != dofs_.num_dofs())
    throw InputError("initial state: " + std::to_string(u0.size()) + " displacements and " +
                     std::to_string(v0.size()) + " velocities, expected " +
                     std::to_string(dofs_.num_dofs()) + " each");
  u_ = u0;
  v_ = v0;
  record_ = StepRecord{};
  std::vector<double> vbar0;
  boundary_values(0.0, vbar0);
  boundary_values(0.5 * dt_, vbar_half_);
  for (int i = 0; i < dofs_.num_dofs(); ++i)
    if (prescribed_[i] >= 0) v_[i] = vbar0[prescribed_[i]];
  restart();
  initialized_ = true;
  record_.initial_balance = record_.balance();
  record_.initial_balance_integer = record_.balance_integer();
}

void CentralDifference::restart(bool cells_unchanged) {
  double elastic = cells_unchanged ? force_.reassemble(dofs_, f_int_, options_.threads)
                                   : force_.compute(dofs_, u_, f_int_, options_.threads);
  elastic += add_coupling(f_int_);
  restart_from(elastic, cells_unchanged);
}

void CentralDifference::set_interface_coupling(const InterfaceCoupling& coupling) {
  if (initialized_) throw InputError("interface coupling: set after initialize()");
  if (coupling.space().num_dofs() != dofs_.num_dofs())
    throw InputError("interface coupling: built on a map of " +
                     std::to_string(coupling.space().num_dofs()) + " DOFs, the integrator's has " +
                     std::to_string(dofs_.num_dofs()));
  coupling_ = &coupling;
}

void CentralDifference::refresh_interfaces() {
  if (!initialized_)
    throw InputError("central difference: refresh_interfaces() before initialize()");
  const double before = record_.kinetic_leapfrog + record_.elastic;
  restart(true);
  record_.activation_energy += record_.kinetic_leapfrog + record_.elastic - before;
}

double CentralDifference::add_coupling(Eigen::VectorXd& f_int) {
  if (!coupling_) return 0.0;
  const Stopwatch clock;
  f_coupling_.setZero(f_int.size());
  const double energy = coupling_->add_forces(u_, f_coupling_);
  f_int -= f_coupling_;
  coupling_seconds_ += clock.seconds();
  return energy;
}

// Inlined into the step's fused loop, whose accumulators then stay in registers (a call per node
// spilled them, and waited on the mesh's vertices: 9 % of a column run at h = 2).
[[gnu::always_inline]] inline void CentralDifference::add_state(int i, double vx, double vy,
                                                                double ax, double ay,
                                                                double* acc) const {
  const double m = mass_node_[i];
  const double x = x0_[2 * i] + u_[2 * i], y = x0_[2 * i + 1] + u_[2 * i + 1];
  acc[3] += 0.5 * m * (vx * vx + vy * vy);
  acc[4] += m * (ax * ax + ay * ay);
  acc[5] += m * vx;
  acc[6] += m * vy;
  acc[7] += m * (x * vy - y * vx);
}

void CentralDifference::restart_from(double elastic, bool cells_unchanged) {
  external_forces(record_.time, f_ext_);
  if (contact_) contact_->restart();  // the state may have jumped: a new work segment
  interface_forces(v_, f_contact_, cells_unchanged);
  bulk_forces(v_, f_bulk_);
  constrain_contact(v_, 0.5, 1.0, f_ext_, f_bulk_, f_contact_);
  const double c = options_.damping;
  a_.resize(dofs_.num_dofs());
  for (int i = 0; i < dofs_.num_dofs(); ++i) {
    const double m = mass_node_[i / 2];
    double applied = f_ext_[i] + f_contact_[i] - f_int_[i] - c * m * v_[i];
    if (bulk_) applied += f_bulk_[i];  // only then: without it the sums keep their bits
    const int j = prescribed_[i];
    // A prescribed DOF accelerates so that its first half step lands on vbar(t + dt/2).
    a_[i] = j < 0 ? applied / m : 2.0 * (vbar_half_[j] - v_[i]) / dt_;
    reaction_[i] = j < 0 ? 0.0 : m * a_[i] - applied;
  }
  std::array<double, 9> sums =
      sum_.sum<9>(dofs_.num_nodes(), options_.threads, [&](int i, double* acc) {
        add_state(i, v_[2 * i], v_[2 * i + 1], a_[2 * i], a_[2 * i + 1], acc);
      });
  book(sums, elastic);
}

void CentralDifference::book(const std::array<double, 9>& sums, double elastic) {
  record_.external_work += sums[0];
  record_.reaction_work += sums[1];
  record_.damping_dissipation += sums[2];
  record_.bulk_viscosity_dissipation += sums[8];
  record_.kinetic = sums[3];
  record_.kinetic_leapfrog = sums[3] - dt_ * dt_ / 8.0 * sums[4];
  record_.elastic = elastic;
  if (contact_) record_.contact_work = contact_->work();
  if (cohesive_) record_.cohesive_work = cohesive_->work();
  record_.momentum = {sums[5], sums[6]};
  record_.angular_momentum = sums[7];
}

const StepRecord& CentralDifference::step() {
  if (!initialized_) throw InputError("central difference: step() before initialize()");
  const long n = record_.step;
  const int dofs = dofs_.num_dofs();
  const int threads = std::max(options_.threads, 1);
  // First half step and the displacement update.
#pragma omp parallel for schedule(static, 2048) num_threads(threads)
  for (int i = 0; i < dofs; ++i) {
    const int j = prescribed_[i];
    v_half_[i] = j < 0 ? v_[i] + 0.5 * dt_ * a_[i] : vbar_half_[j];
    u_[i] += dt_ * v_half_[i];
  }
  const double t_next = double(n + 1) * dt_;
  double elastic = force_.compute(dofs_, u_, f_int_, threads);
  elastic += add_coupling(f_int_);
  external_forces(t_next, f_ext_next_);
  interface_forces(v_half_, f_contact_next_);
  bulk_forces(v_half_, f_bulk_next_);
  constrain_contact(v_half_, 1.0, 1.0 + 0.5 * options_.damping * dt_, f_ext_next_, f_bulk_next_,
                    f_contact_next_);
  boundary_values(t_next + 0.5 * dt_, vbar_next_half_);
  // Second half step, fused with the bookkeeping of the work done over the step.
  // Copies, not members or references: those are reloaded after every store to v_, a_, reaction_.
  const double c = options_.damping, dt = dt_;
  // One DOF: its velocity v and acceleration a at the step's end, and its work over the step.
  auto advance = [&, c, dt](int i, double m, double* acc, double& v, double& a) {
    const int j = prescribed_[i];
    const double vh = v_half_[i], du = dt * vh;
    double applied = f_ext_next_[i] + f_contact_next_[i] - f_int_[i];
    if (bulk_) {
      applied += f_bulk_next_[i];
      acc[8] -= 0.5 * du * (f_bulk_[i] + f_bulk_next_[i]);
    }
    a = j < 0 ? (applied - c * m * vh) / (m * (1.0 + 0.5 * c * dt))
              : (vbar_next_half_[j] - vbar_half_[j]) / dt;
    v = vh + 0.5 * dt * a;
    const double r = j < 0 ? 0.0 : m * a - (applied - c * m * v);
    acc[0] += 0.5 * du * (f_ext_[i] + f_ext_next_[i]);
    acc[1] += 0.5 * du * (reaction_[i] + r);
    acc[2] += 0.5 * du * c * m * (v_[i] + v);
    v_[i] = v;
    a_[i] = a;
    reaction_[i] = r;
  };
  auto second_half = [&](int node, double* acc) {
    const double m = mass_node_[node];
    double vx, vy, ax, ay;
    advance(2 * node, m, acc, vx, ax);
    advance(2 * node + 1, m, acc, vy, ay);
    add_state(node, vx, vy, ax, ay, acc);
  };
  const auto sums = sum_.sum<9>(dofs_.num_nodes(), threads, second_half);
  std::swap(f_ext_, f_ext_next_);
  std::swap(f_contact_, f_contact_next_);
  std::swap(f_bulk_, f_bulk_next_);
  std::swap(vbar_half_, vbar_next_half_);
  record_.step = n + 1;
  record_.time = t_next;
  book(sums, elastic);
  return record_;
}

void CentralDifference::remap(SplitDofMap dofs) {
  if (coupling_) throw InputError("remap: the interface coupling is built on the current map");
  if (!initialized_) throw InputError("central difference: remap() before initialize()");
  const double before = record_.kinetic_leapfrog + record_.elastic;
  const SplitDofMap old = std::move(dofs_);
  const Eigen::VectorXd u_old = u_, v_old = v_;
  dofs_ = std::move(dofs);
  bind();
  // Per new node: its first old node, and whether all its pairs share it.
  const int nodes = dofs_.num_nodes();
  std::vector<int> source(nodes, -1);
  std::vector<char> single(nodes, 1);
  for (int c = 0; c < mesh_.num_cells(); ++c)
    for (int k = 0; k < mesh_.cell_size(c); ++k) {
      const int to = dofs_.node(c, k), from = old.node(c, k);
      if (source[to] < 0) source[to] = from;
      if (source[to] != from) single[to] = 0;
    }
  const bool split = std::all_of(single.begin(), single.end(), [](char s) { return s != 0; });
  // Merged nodes take their pairs' mass-weighted means.
  Eigen::VectorXd mu, mv;
  if (!split) {
    mu = mv = Eigen::VectorXd::Zero(2 * nodes);
    for (int c = 0; c < mesh_.num_cells(); ++c)
      for (int k = 0; k < mesh_.cell_size(c); ++k) {
        const int to = dofs_.node(c, k), from = old.node(c, k);
        mu.segment<2>(2 * to) += mass_.pair_mass(c, k) * u_old.segment<2>(2 * from);
        mv.segment<2>(2 * to) += mass_.pair_mass(c, k) * v_old.segment<2>(2 * from);
      }
  }
  u_.resize(2 * nodes);
  v_.resize(2 * nodes);
  for (int i = 0; i < nodes; ++i) {
    // A split copies exactly (a mean of equal values need not round to the value).
    u_.segment<2>(2 * i) = single[i] ? u_old.segment<2>(2 * source[i]).eval()
                                     : (mu.segment<2>(2 * i) / mass_node_[i]).eval();
    v_.segment<2>(2 * i) = single[i] ? v_old.segment<2>(2 * source[i]).eval()
                                     : (mv.segment<2>(2 * i) / mass_node_[i]).eval();
  }
  // A split leaves every cell's displacements as they were at the last force evaluation.
  restart(split);
  record_.remap_energy += record_.kinetic_leapfrog + record_.elastic - before;
}

void CentralDifference::disconnect(const std::vector<char>& connected, std::span<const int> edges) {
  if (coupling_) throw InputError("disconnect: the interface coupling is built on the current map");
  if (!initialized_) throw InputError("central difference: disconnect() before initialize()");
  const double before = record_.kinetic_leapfrog + record_.elastic;
  const int old_nodes = dofs_.num_nodes();
  const SplitDofMap::Split split = dofs_.disconnect(mesh_, connected, edges);
  const int nodes = dofs_.num_nodes();
  // A split-off node copies its source's state, so every cell keeps its displacements.
  prescribed_.resize(2 * nodes);
  for (Eigen::VectorXd* x : {&u_, &v_, &f_int_, &x0_}) x->conservativeResize(2 * nodes);
  for (int j = old_nodes; j < nodes; ++j) {
    const int from = split.source[j - old_nodes];
    for (int d = 0; d < 2; ++d) {
      x0_[2 * j + d] = x0_[2 * from + d];
      prescribed_[2 * j + d] = prescribed_[2 * from + d];
      u_[2 * j + d] = u_[2 * from + d];
      v_[2 * j + d] = v_[2 * from + d];
    }
  }
  // What restart_from and the next step overwrite: sized only.
  for (Eigen::VectorXd* x :
       {&reaction_, &f_ext_next_, &v_half_, &f_contact_next_, &f_bulk_, &f_bulk_next_})
    x->resize(2 * nodes);
  mass_node_.conservativeResize(nodes);
  for (int i : split.nodes) mass_node_[i] = mass_.node_mass(dofs_, i);
  force_.reassemble_nodes(dofs_, split.nodes, f_int_);
  if (contact_) contact_->rebind(dofs_, mass_node_, split.nodes);
  if (cohesive_) cohesive_->rebind(dofs_, split.vertices);
  restart_from(record_.elastic, true);  // the cells, and so their energies, are unchanged
  record_.remap_energy += record_.kinetic_leapfrog + record_.elastic - before;
}

void CentralDifference::archive(StateArchive& a) {
  if (!initialized_) throw InputError("central difference: archive() before initialize()");
  dofs_.archive(a);
  if (a.loading()) bind();
  for (auto [name, x] : {std::pair{"u", &u_},
                         {"v", &v_},
                         {"a", &a_},
                         {"f_int", &f_int_},
                         {"f_ext", &f_ext_},
                         {"f_ext_next", &f_ext_next_},
                         {"reaction", &reaction_},
                         {"f_contact", &f_contact_},
                         {"f_contact_next", &f_contact_next_},
                         {"f_bulk", &f_bulk_},
                         {"f_bulk_next", &f_bulk_next_},
                         {"v_half", &v_half_}})
    a.vector(std::string("run.") + name, *x);
  a.vector("run.vbar_half", vbar_half_);
  a.vector("run.vbar_next_half", vbar_next_half_);
  a.value("run.record", record_);
  force_.archive(a);
}

}  // namespace vorodg
