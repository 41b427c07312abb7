#pragma once
// Explicit central differences in velocity Verlet form on the node DOFs of a split (cell,
// vertex) DOF map (report section 6), with lumped masses:
//     v_{n+1/2} = v_n + dt/2 a_n
//     u_{n+1}   = u_n + dt v_{n+1/2}
//     f_int     = K u_{n+1}                                  (cell by cell, InternalForce)
//     a_{n+1}   = (f_ext - f_int - c M v_{n+1}) / M,    v_{n+1} = v_{n+1/2} + dt/2 a_{n+1}
// The damping velocity v_{n+1} is the centred one; with a diagonal M the equation for a_{n+1}
// is solved in closed form, a = (f_ext - f_int - c M v_{n+1/2}) / (M (1 + c dt/2)). This is the
// classic damped central difference (velocity (u_{n+1} - u_{n-1}) / 2dt), whose stability limit
// is 2/omega_max whatever c, so StableTimeStep applies unchanged.
//
// Prescribed velocities act on the half-step velocities: v_{n+1/2} = vbar(t_{n+1/2}) exactly.
// Their acceleration is the one those imply, a_n = (vbar(t_{n+1/2}) - vbar(t_{n-1/2})) / dt
// (a_0 = 2 (vbar(dt/2) - vbar(0)) / dt), and the reaction is R = M a - (f_ext - f_int - c M v):
// the force the constraint must apply. With it the energy balance of StepRecord closes.
//
// Contact (set_contact, optional): ContactForces adds the forces of surface-to-surface contact
// and of rigid planes at every evaluation, from the displacements u_{n+1} and the half-step
// velocities v_{n+1/2} (only contact damping reads them; v_0 at the start). They enter the
// acceleration like applied forces but are kept apart, so that their work (booked by
// ContactWork as the trapezoid over the step) goes to StepRecord::contact_work.
//
// Kinematic contact (ContactForces::kinematic: the exact plane and cell-pair laws): once every
// other force of the step is known, each node's next half-step velocity is predicted, the laws'
// impulses keep the next positions admissible, and they come back as contact forces of this
// step (f = (1 + c dt/2) J / dt; at a restart, where v_{1/2} = v_0 + dt/2 a_0, f = 2 J / dt).
// They are in f_contact like the penalty laws' forces, so accelerations, momenta and the work
// account take them in without a special case.
//
// Interfaces coupled from the start (set_interface_coupling, optional): InterfaceCoupling's
// interior-penalty forces join the internal force, and their energy 1/2 u.K_F u the elastic
// energy, so the balance closes to round-off with them (they are linear in u). An interface
// activated as a crack leaves the coupling for a cohesive face (refresh_interfaces); the jump of
// K* + elastic at that instant is booked as StepRecord::activation_energy.
//
// Cohesive cracks (set_cohesive, optional): CohesiveForces adds the tractions of the cohesive
// law on the cracked edges at the same evaluations, into the same interface force vector, and
// books its own share of the trapezoid, which goes to StepRecord::cohesive_work.
//
// Bulk viscosity (set_bulk_viscosity, optional): BulkViscosity's cell forces -q A b_k, taken
// from the same velocities as contact (v_{n+1/2}; v_n at a restart), so they lag half a step
// behind like any explicit viscosity: that is what lowers the stable step by
// sqrt(1 + xi^2) - xi. They enter the acceleration like applied forces, and their work, booked
// as the trapezoid over the step like the damping's, goes to
// StepRecord::bulk_viscosity_dissipation (with its sign turned: energy taken out is positive).
//
// Every loop is parallel over cells or nodes, writing its own slots, and every sum is an
// OrderedSum: results are bit-for-bit the same for any thread count.
#include <Eigen/Core>
#include <array>
#include <functional>
#include <span>
#include <vector>

#include "core/dofs/SplitDofMap.hpp"
#include "core/mesh/PolygonMesh.hpp"
#include "dynamics/BulkViscosity.hpp"
#include "dynamics/CohesiveForces.hpp"
#include "dynamics/ContactForces.hpp"
#include "dynamics/InterfaceCoupling.hpp"
#include "dynamics/InternalForce.hpp"
#include "dynamics/LumpedMass.hpp"
#include "dynamics/OrderedSum.hpp"
#include "dynamics/StepRecord.hpp"
#include "dynamics/VelocityBoundary.hpp"

namespace vorodg {

class StateArchive;

struct DynamicsOptions {
  double damping = 0.0;  // mass-proportional damping c (1/s): force -c M v
  int threads = 1;
};

class CentralDifference {
 public:
  /// Body force per unit mass, a function of time.
  using BodyForce = std::function<Eigen::Vector2d(double)>;
  /// Extra applied nodal forces at (t, u), added into f (node DOFs), e.g. contact.
  using ExternalForce = std::function<void(double, const Eigen::VectorXd&, Eigen::VectorXd&)>;

  /// `mesh` and `mass` must outlive the integrator. Throws InputError unless dt > 0 and c >= 0.
  CentralDifference(const PolygonMesh& mesh, const LumpedMass& mass, InternalForce force,
                    SplitDofMap dofs, double dt, const DynamicsOptions& options = {});

  // Loads and boundaries: set before initialize().
  void set_body_force(BodyForce b) { body_force_ = std::move(b); }
  void set_external_force(ExternalForce f) { external_force_ = std::move(f); }
  /// Contact forces at every step; `contact` must outlive the integrator (it keeps the contact
  /// reports and the work account). Throws InputError after initialize().
  void set_contact(ContactForces& contact);
  /// Cohesive tractions on cracked edges at every step; `cohesive` must outlive the integrator.
  /// It may be set or grown (CohesiveForces::add_edge, then remap) at any time.
  void set_cohesive(CohesiveForces& cohesive);
  /// Interfaces held together by interior-penalty terms; `coupling` must outlive the
  /// integrator and be built on dofs(). Throws InputError after initialize() or for another
  /// map's coupling. The map may no longer be remapped.
  void set_interface_coupling(const InterfaceCoupling& coupling);
  /// After interfaces of the coupling were deactivated and the cohesive faces that replace them
  /// added and bound (InterfaceActivation): the forces at the current state are recomputed
  /// (cells unchanged) and the change of K* + elastic goes to activation_energy.
  void refresh_interfaces();
  /// Bulk viscosity on the cells at every step; `bulk` must outlive the integrator. Throws
  /// InputError after initialize().
  void set_bulk_viscosity(BulkViscosity& bulk);
  /// Throws InputError naming the vertex if a DOF is prescribed twice or a vertex is unknown,
  /// and after initialize().
  void add_velocity_boundary(VelocityBoundary bc);

  /// State at t = 0 (node DOF vectors of dofs()); prescribed DOFs take vbar(0). Computes a_0,
  /// the reactions and the step-0 record.
  void initialize(const Eigen::VectorXd& u0, const Eigen::VectorXd& v0);
  /// One step; returns its record. Throws InputError before initialize().
  const StepRecord& step();

  /// Rebinds the state to another DOF map of the same mesh (nodes split or merged). Each new
  /// node takes the mass-weighted mean of the old nodes of its pairs: a copy when they are all
  /// one node (a split), so momentum and kinetic energy are kept. Accelerations and reactions
  /// are recomputed at the current time; the change of K* + elastic goes to remap_energy.
  /// Throws InputError before initialize().
  void remap(SplitDofMap dofs);
  /// The same for the split of the current map by disconnecting `edges` (`connected` the new
  /// edge set; SplitDofMap::disconnect), at a cost that follows the split rather than the mesh:
  /// the split-off nodes are appended and copy their source's state, and only the masses and
  /// internal forces of the nodes at the split vertices are recomputed. Bit for bit what remap
  /// gives for the same classes, up to the node numbering (and the record's sums, which add the
  /// nodes in their order).
  void disconnect(const std::vector<char>& connected, std::span<const int> edges);

  /// Wall seconds so far in the interface coupling's forces (what coupled interfaces cost).
  double coupling_seconds() const { return coupling_seconds_; }
  double dt() const { return dt_; }
  double time() const { return record_.time; }
  long step_count() const { return record_.step; }
  const StepRecord& record() const { return record_; }
  const SplitDofMap& dofs() const { return dofs_; }
  const InternalForce& force() const { return force_; }
  /// For GlobalTimeStep on the current map (it overwrites the per-cell buffers only).
  InternalForce& force() { return force_; }
  const Eigen::VectorXd& displacement() const { return u_; }
  const Eigen::VectorXd& velocity() const { return v_; }
  const Eigen::VectorXd& acceleration() const { return a_; }
  const Eigen::VectorXd& internal_force() const { return f_int_; }
  /// The contact and cohesive forces of the last evaluation (zero without either).
  const Eigen::VectorXd& interface_force() const { return f_contact_; }
  /// The bulk viscosity forces of the last evaluation (zero without it).
  const Eigen::VectorXd& bulk_viscosity_force() const { return f_bulk_; }
  const ContactForces* contact() const { return contact_; }
  /// Reaction forces at the prescribed DOFs (zero elsewhere).
  const Eigen::VectorXd& reaction() const { return reaction_; }
  /// Per node (not per DOF).
  const Eigen::VectorXd& node_masses() const { return mass_node_; }
  /// Reference position of node i (its mesh vertex).
  Point node_position(int i) const { return {x0_[2 * i], x0_[2 * i + 1]}; }
  /// The boundary (index in add order) prescribing a node DOF, or -1 if the DOF is free.
  int prescribed_boundary(int dof) const { return prescribed_[dof]; }

  /// Saves or loads the state the next step reads: the DOF map (loading rebinds the attached
  /// laws to it), the displacements, velocities and accelerations, the forces carried from one
  /// step to the next and the record with its energy accounts. The attached laws archive their
  /// own state (ExplicitSimulation::archive).
  void archive(StateArchive& a);

 private:
  void bind();
  void external_forces(double t, Eigen::VectorXd& f);
  /// Contact and cohesive forces at the current displacements and velocities v (zero without
  /// either). `openings_unchanged` (after a split): the faces' forces of the last evaluation
  /// are gathered onto the current nodes instead of evaluated again.
  void interface_forces(const Eigen::VectorXd& v, Eigen::VectorXd& f,
                        bool openings_unchanged = false);
  void boundary_values(double t, std::vector<double>& out) const;
  /// Accelerations, reactions, forces and the record's state at the current time from u_ and v_
  /// (after initialize or remap). `cells_unchanged`: every cell's displacements are those of the
  /// last force evaluation (a split), so the internal force is reassembled, not recomputed.
  void restart(bool cells_unchanged = false);
  /// The rest of restart once the internal force and the elastic energy are known.
  void restart_from(double elastic, bool cells_unchanged);
  /// The kinematic contact laws' forces into f_contact, given the other forces of the same
  /// evaluation: each free node moves next at w + beta dt a (a from those forces), and
  /// `inertia` is what a force is divided by beyond the mass (1 + c dt/2 in a step, 1 at a
  /// restart).
  void constrain_contact(const Eigen::VectorXd& w, double beta, double inertia,
                         const Eigen::VectorXd& f_ext, const Eigen::VectorXd& f_bulk,
                         Eigen::VectorXd& f_contact);
  /// Bulk viscosity forces at velocities v into f (zero without it).
  void bulk_forces(const Eigen::VectorXd& v, Eigen::VectorXd& f);
  /// The record's state from per-step sums: work increments (external, reaction, damping), then
  /// kinetic, a.M a, momentum x, y, angular momentum, then bulk viscosity's dissipation.
  void book(const std::array<double, 9>& sums, double elastic);
  /// Adds node i's state at velocity v and acceleration a to sums[3..7]. The caller passes them
  /// from registers where it has just computed them: reloading a pair just stored as two scalars
  /// stalls on the failed store forwarding (a fifth of a column run's time).
  void add_state(int i, double vx, double vy, double ax, double ay, double* sums) const;

  const PolygonMesh& mesh_;
  const LumpedMass& mass_;
  InternalForce force_;
  SplitDofMap dofs_;
  double dt_;
  DynamicsOptions options_;
  BodyForce body_force_;
  ExternalForce external_force_;
  ContactForces* contact_ = nullptr;
  CohesiveForces* cohesive_ = nullptr;
  const InterfaceCoupling* coupling_ = nullptr;
  Eigen::VectorXd f_coupling_;  // scratch: the coupling's force -K_F u
  double coupling_seconds_ = 0.0;
  /// f_int += K_F u of the coupling (none: nothing); returns its energy.
  double add_coupling(Eigen::VectorXd& f_int);
  BulkViscosity* bulk_ = nullptr;
  std::vector<VelocityBoundary> boundaries_;

  Eigen::VectorXd x0_;           // per node: its vertex's position (x, y), read where u is
  std::vector<int> prescribed_;  // per DOF: boundary index or -1
  Eigen::VectorXd mass_node_;
  Eigen::VectorXd u_, v_, a_, f_int_, f_ext_, f_ext_next_, reaction_;
  Eigen::VectorXd f_contact_, f_contact_next_;
  Eigen::VectorXd f_bulk_, f_bulk_next_;
  Eigen::VectorXd v_half_;
  std::vector<Point> predicted_;  // per node: the next half-step velocity kinematic contact sees
  std::vector<char> held_;        // per node: whether a prescribed velocity holds it
  std::vector<double> vbar_half_, vbar_next_half_;  // vbar(t_{n+1/2}), vbar(t_{n+3/2})
  StepRecord record_;
  OrderedSum sum_;
  bool initialized_ = false;
};

}  // namespace vorodg
