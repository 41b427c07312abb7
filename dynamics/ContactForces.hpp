#pragma once
// Contact in the integrator: the bridge from CentralDifference's node DOFs to dynamics/contact,
// which works per (cell, vertex) pair and knows nothing of the integrator (the dependency runs
// one way: dynamics links contact, contact never includes dynamics/).
//
// Each evaluation reads the node displacements and velocities as pair positions x = X + u and
// pair velocities (of the surface cells' pairs: no other pair is ever touched), lets each of its
// contact laws (ContactLaw: SurfaceContact between surface cells of every body of the mesh, and
// obstacles such as rigid planes) add their forces per pair, sums the pairs of each node into the
// nodal force, and books the work of those forces with ContactWork: the trapezoid (f_n + f_n+1) / 2
// . (x_n+1 - x_n), which with central differences is exactly the change the contact forces make in
// the half-step kinetic energy. So StepRecord's balance closes with contact to the integrator's
// round-off, whatever the penalty law does.
//
// Kinematic laws (ContactLaw::kinematic: ExactPlane, ExactSurfaceContact) add nothing at that
// evaluation; the integrator calls constrain() once every other force of the step is known, with
// each node's predicted next half-step velocity, and their impulses come back as forces of the
// step (KinematicState). Their work is booked the same way, in two accounts: the normal impulses'
// (a plastic impact takes energy, up to the trapezoid's O(dt) share of the other forces' work)
// and the friction impulses'.
//
// Friction (ContactFriction) follows the contact's tangential motion from one evaluation to the
// next; an evaluation repeated at the same positions (after restart) sees none.
//
// Surface contact forces of a pair are equal and opposite (PolygonPenetration), so they move no
// momentum; an obstacle's forces are external (it takes the reaction: ContactLaw::external) and
// are reported apart, as the "plane" report and net force on the mesh.
#include <Eigen/Core>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/dofs/SplitDofMap.hpp"
#include "core/mesh/PolygonMesh.hpp"
#include "dynamics/contact/ContactFriction.hpp"
#include "dynamics/contact/ContactLaw.hpp"
#include "dynamics/contact/ContactReport.hpp"
#include "dynamics/contact/ContactWork.hpp"
#include "dynamics/contact/PenaltyContact.hpp"
#include "dynamics/contact/SurfaceCells.hpp"

namespace vorodg {

class StateArchive;

class ContactForces {
 public:
  /// `mesh` must outlive this object. `surfaces`: contact between the surface cells of the mesh
  /// by the registered law `surface_law` (ContactLaws; off: obstacles only), with Coulomb
  /// friction `friction`; `law` is the penalty law of the penalty laws. The grid of the surface
  /// search starts at the mesh's h_avg.
  ContactForces(const PolygonMesh& mesh, const PenaltyContact& law, bool surfaces = true,
                const ContactFriction& friction = ContactFriction{},
                const std::string& surface_law = "penalty-cell-pairs");

  /// One more contact law, evaluated after those added before it.
  void add_law(std::unique_ptr<ContactLaw> law);
  /// The law "penalty-plane": a fixed rigid half-plane with the same penalty law and its own
  /// friction; `normal` points into free space.
  void add_plane(const Point& point, const Point& normal,
                 const ContactFriction& friction = ContactFriction{});
  /// The surface cells (grow it as cracks expose new surface).
  SurfaceCells& surface() { return surface_; }
  const SurfaceCells& surface() const { return surface_; }
  const PenaltyContact& law() const { return law_; }
  bool surfaces() const { return surfaces_; }

  // What CentralDifference calls.
  /// Takes the node of every pair and the node masses of a DOF map (again after a remap).
  void bind(const SplitDofMap& dofs, const Eigen::VectorXd& node_masses);
  /// The next evaluation starts a new segment of the work account (at initialize and after a
  /// remap, where the state jumps): the work booked so far is kept.
  void restart();
  /// bind for the listed nodes alone (every other node kept its pairs and mass): after a split
  /// (SplitDofMap::disconnect), the nodes at the split vertices.
  void rebind(const SplitDofMap& dofs, const Eigen::VectorXd& node_masses,
              std::span<const int> nodes);
  /// Sets f (node DOFs, resized) to the contact forces at node displacements u and velocities v
  /// (the half-step velocities of central differences, read only by contact damping) with step
  /// dt, and books their work. Throws InputError before bind().
  void evaluate(const Eigen::VectorXd& u, const Eigen::VectorXd& v, double dt, Eigen::VectorXd& f);

  /// Whether a kinematic law is among the laws: then the integrator must call constrain().
  bool kinematic() const { return kinematic_; }
  /// What the integrator predicts for every node without the kinematic laws (node i at [i]):
  /// its next half-step velocity, and whether the loads hold it (a prescribed velocity: it takes
  /// no impulse). Whole arrays, filled by one pass over the nodes: a call per pair cost the
  /// column 16 % of its run.
  struct Prediction {
    std::span<const Point> velocity;
    std::span<const char> held;
  };
  /// The kinematic laws, after evaluate() at the same displacements, once every other force of
  /// the step is known: each node moves next by dt v' with v' = next.velocity = w + beta dt a.
  /// Adds to f (node DOFs) the forces inertia J / (beta dt) of the laws' impulses J (inertia:
  /// 1 + c dt / 2 with mass damping c, 1 at a restart), adds them to the pair forces and the
  /// reports, and books their work. Nothing without a kinematic law. Throws InputError unless
  /// the prediction has one entry per node of the bound map.
  void constrain(const Prediction& next, double beta, double inertia, Eigen::VectorXd& f);

  /// The work of the contact forces on the mesh so far (ContactWork, over every segment).
  double work() const { return work_.work() + impulse_work_.work() + friction_work_.work(); }
  /// Of that work, what friction has dissipated so far (surfaces and planes; >= 0): the penalty
  /// laws' slip work, and the work of the kinematic laws' friction impulses.
  double friction_dissipated() const { return friction_dissipated_ - friction_work_.work(); }
  /// Of that work, what was taken at approach so far: by a velocity penalty (damping or plastic;
  /// minus the trapezoid work of its part of the forces) and by the kinematic laws' normal
  /// impulses (minus their work). 0 with neither.
  double velocity_penalty_dissipated() const {
    return -(velocity_work_.work() + impulse_work_.work());
  }
  /// Of the last evaluation: between surface cells, and against the obstacles (planes).
  const ContactReport& surface_report() const { return surface_report_; }
  const ContactReport& plane_report() const { return plane_report_; }
  /// Both together.
  ContactReport report() const {
    ContactReport all = surface_report_;
    all += plane_report_;
    return all;
  }
  /// Per pair, the planes' share of pair_forces() (zero without planes).
  std::span<const Point> plane_pair_forces() const { return plane_pair_force_; }
  /// Net force of the planes on the mesh at the last evaluation.
  const Point& plane_force() const { return plane_force_; }
  /// Per pair (the mesh's CSR layout), the contact forces of the last evaluation.
  std::span<const Point> pair_forces() const { return force_; }
  /// The pairs that surface contact or a plane pushed at the last evaluation, ascending: every
  /// other pair's force is zero.
  std::span<const int> pushed_pairs() const { return support_; }
  /// Whether a vertex of cell a lies inside cell b or one of b inside a, at the positions of
  /// the last evaluation: what surface contact would push apart (PolygonPenetration's test).
  /// False before the first evaluation. Throws InputError unless both are surface cells.
  bool overlapping(int a, int b) const;

  /// Saves or loads the surface, every law's state, the last evaluation and the work accounts
  /// (a checkpoint; the integrator rebinds the pairs to its map first).
  void archive(StateArchive& a);

 private:
  void gather_state(const Eigen::VectorXd& u, const Eigen::VectorXd& v);
  /// Zeroes the pair forces of the last evaluation (the other pairs are zero already).
  void clear_forces();
  /// Lists the pairs with a force (what contact and the planes pushed), adds the planes' pair
  /// forces in and sums their net force.
  void collect_support();
  /// Node i's number and mass on each of its pairs.
  void bind_node(const SplitDofMap& dofs, const Eigen::VectorXd& node_masses, int i);
  /// The kinematic laws' per-node buffers for `nodes` nodes.
  void size_nodes(int nodes);

  const PolygonMesh& mesh_;
  PenaltyContact law_;
  bool surfaces_;
  SurfaceCells surface_;
  std::vector<std::unique_ptr<ContactLaw>> laws_;  // in evaluation order
  bool obstacles_ = false;                         // whether one of them is external
  SegmentedWork work_;                             // the force laws' forces
  double friction_dissipated_ = 0.0;               // the force laws' slip work
  SegmentedWork velocity_work_;                    // the velocity penalty's part alone
  std::vector<Point> velocity_force_;  // per pair: that part of force_ (empty without one)
  // Kinematic laws: per node, the predicted velocity, 1 / m (0: held) and the impulses of a
  // constrain(); per pair, the forces they became (normal and friction) and the pairs carrying
  // them; the work of each.
  bool kinematic_ = false;
  std::vector<Point> node_velocity_, normal_impulse_, friction_impulse_;
  std::vector<double> inverse_mass_;
  std::vector<double> node_inverse_mass_;  // per node, 1 / m of the bound map
  std::vector<Point> impulse_force_, friction_force_;
  std::vector<int> impulse_support_;
  SegmentedWork impulse_work_, friction_work_;
  double dt_ = 0.0;  // of the last evaluation
  /// Turns the impulses at the nodes of `law`'s touched pairs into forces (to_force J) on one
  /// pair each, into f, the pair forces and, for an obstacle, the plane's forces.
  void collect_impulses(const ContactLaw& law, double to_force, Eigen::VectorXd& f);
  bool repeat_ = false;  // the next evaluation is at the positions of the last one (restart)

  std::vector<Point> reference_;  // X per pair
  std::vector<int> node_;         // node per pair, of the bound map
  std::vector<double> mass_;      // node mass per pair
  std::vector<Point> position_, velocity_, force_, plane_pair_force_;
  std::vector<int> support_;  // the pairs with a force at the last evaluation
  bool evaluated_ = false;
  int num_dofs_ = -1;
  ContactReport surface_report_, plane_report_;
  Point plane_force_ = Point::Zero();
};

}  // namespace vorodg
