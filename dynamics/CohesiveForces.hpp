#pragma once
// Cohesive tractions on the cracked edges of explicit dynamics (report sections 4 and 6): the
// same face kernel as quasi-static fracture (fracture/FacePoint: the CohesiveLaw with the closure
// penalty), acting between the nodes a crack has split.
//
// Geometry. Edge e runs v0 -> v1 as cell0 traverses it; its normal n points from cell0 to
// cell1 and its tangent is t = (v1 - v0) / L. Cell displacements are linear along an edge
// between its end vertices (the RK shape functions restrict to the edge's hat functions), so the
// opening g = u_cell1 - u_cell0 is linear between the jumps of the two end nodes. Two Gauss points
// per edge, each with its own history, carry the law on g in the frame (g.n, g.t); the law
// starts from zero opening and puts no normal traction on a closing face. Against overclosure
// a penalty k <g_n>_- acts at each point, k a fraction of K0 (closure_stiffness; within the
// springs' bound below): surface contact leaves cells that share a vertex to it
// (docs/contact.md), and the faces of a crack share two. Its energy k <g_n>_-^2 / 2 is stored,
// not dissipated.
//
// Release. The penalty measures overclosure along the face's reference normal, which means
// nothing once the two sides have moved apart and turned: left on, it tethers fragments that
// have flown apart, and switches on with overlaps of metres when they tumble. So a face may be
// released, for good, once it is fully broken, both its points are open (g_n >= 0) at the last
// evaluation and both its ends have come apart by at least the face's length (`releasable`).
// The first two make the release free of energy: a broken point carries no law traction and an
// open one no penalty, so the face stores nothing when it lets go. Who releases it
// (DynamicFracture) also checks that the two cells do not overlap, so that surface contact,
// which keeps them apart from then on (SurfaceCells::release), starts from zero force too.
//
// Which law. Only an initially elastic (intrinsic) law is accepted, inserted extrinsically:
// the edge is intact until the criterion holds, then the law starts from zero opening and zero
// traction, rises with stiffness K0 to sigma_c at delta_0 = sigma_c / K0, and softens with area
// G. A purely extrinsic law would start at sigma_c, and its unloading secant T(delta_max) /
// delta_max has no bound as delta_max -> 0: faces that open a little and close again (most of
// them, when many cracks form at once) become springs far stiffer than the cells, and the
// explicit step is no longer stable. Measured on a stretched strip: the work the integrator
// booked missed the law's closed form by 30 % at 0.5 x the cell step, by 0.3 % at 0.05 x.
// With K0 the springs are bounded; eigenvalue_bound() gives their share of the step.
//
// Work. Every force is a linear map of a point's force w (tau_n n + tau_t t) with the same
// operator that gives the point's jump g from the node displacements, so the trapezoid of the
// nodal forces over a step equals, point by point, -(F_n + F_n+1) / 2 . (g_n+1 - g_n), in the
// global frame: exact whether or not the face's frame turns. That is what work() sums:
// exactly the cohesive share of CentralDifference's discrete energy identity. It does not depend
// on the DOF map, so it runs on across node splits (a split copies the displacements, so no
// opening jumps). The law's closed forms (dissipated and stored energy) are given beside it: the
// two agree as the step shrinks, and their difference is the time discretization's error.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <span>
#include <vector>

#include "core/dofs/SplitDofMap.hpp"
#include "core/mesh/PolygonMesh.hpp"
#include "dynamics/LumpedMass.hpp"
#include "dynamics/StableTimeStep.hpp"
#include "fracture/CohesiveLaw.hpp"
#include "fracture/FacePoint.hpp"

namespace vorodg {

class StateArchive;

/// The crack faces' penalty k <g_n>_- against overclosure. By default a fraction of K0 on every
/// face: at K0 itself a closing face is a spring whose contact lasts about one step at the stable
/// step, and the switching of such a spring on and off feeds energy in (measured: half the
/// initial energy on a stretched strip at safety 0.9); at a tenth its contact lasts about three
/// times longer. Or one stiffness per mesh edge: with interfaces coupled from the start each
/// face keeps its interface's penalty eps, the closure of the quasi-static solver
/// (dg/CohesiveInterfaces), so that the two solve the same equations (docs/dynamics.md).
struct ClosureStiffness {
  static constexpr double kDefaultFraction = 0.1;
  double fraction = kDefaultFraction;
  std::vector<double> per_edge;  // per unit thickness (Pa/m); empty: fraction x K0 everywhere
  double of_edge(int e, double k0) const { return per_edge.empty() ? fraction * k0 : per_edge[e]; }
};

class CohesiveForces {
 public:
  /// `mesh` and `law` must outlive this object. Throws InputError unless the law is intrinsic
  /// (initial_stiffness > 0).
  CohesiveForces(const PolygonMesh& mesh, const CohesiveLaw& law);

  /// A strength varying from edge to edge (MaterialVariation::edge_strength): edge e's law has
  /// strength factor[e] x sigma_c, with G and K0 unchanged. Call before the first add_edge.
  /// Throws InputError naming the edge where the scaled law is invalid, or if edges cracked.
  void set_edge_strength(std::vector<double> factor);
  /// The overclosure penalty (ClosureStiffness): a fraction of K0 on every face, or a stiffness
  /// per mesh edge. Call before the first add_edge. Throws InputError unless 0 < fraction <= 1,
  /// or per edge one finite value > 0 for each mesh edge.
  void set_closure(ClosureStiffness closure);
  /// Coulomb friction mu on the closed faces (fracture/FacePoint: a stick spring of the closure
  /// stiffness, slipping at mu times the closure's pressure). Throws InputError unless
  /// 0 <= mu <= 10 (finite). 0, the default, is frictionless.
  void set_friction(double mu);
  double friction() const { return friction_; }
  /// Whether each face reads its opening in a frame that turns with it (for corotational
  /// kinematics, where fragments spin): the line through the mean current positions of its two
  /// sides' ends. Off (the default), the reference frame, which a turned face misreads: a
  /// normal opening of a face turned by theta is read as cos theta normal, sin theta shear.
  /// The face's energy then depends on its frame too, and its force is the exact gradient: the
  /// traction's part plus, on the chord d, dE/dd = w (tau_t g_n - tau_n g_t) / |d| n (the
  /// opening's normal and tangential parts turn with d: dg_n/dd = -g_t n / |d|, dg_t/dd =
  /// g_n n / |d|). Without it the closure and friction forces are not conservative in a turning
  /// frame, and spinning, closed faces fed energy in (measured: column runs blew up). It
  /// vanishes where the traction is parallel to the opening (the law with beta = 1).
  void set_turning_frames(bool on) { turning_ = on; }
  /// Interior edge e cracks: its points start from zero opening. Throws InputError for a
  /// boundary edge or an edge already cracked.
  void add_edge(int e);
  /// What an interface carried when it was activated (InterfaceActivation): at each Gauss point
  /// (from v0) the jump u_cell1 - u_cell0 (global) and the traction (normal, tangential) of the
  /// face frame that held it together.
  struct Carried {
    std::array<Eigen::Vector2d, 2> jump, traction;
  };
  /// Interior edge e cracks carrying `carried`: each point continues with the law from the
  /// traction it carried, so nothing is released. The law's opening is the jump since then plus
  /// the point on the elastic branch (and the closure penalty, in compression) whose traction is
  /// the carried one: d = (g - g_0) + s, tau(s) = tau_0. Where the carried traction is beyond
  /// the law's peak, s is the peak in the carried direction and the difference is released
  /// (activation_work()); without a shear factor (beta = 0) the law carries no shear.
  void add_edge(int e, const Carried& carried);
  /// The law's energy stored at the starting points s of the edges added with add_edge(e,
  /// carried), summed: the energy the law starts with, which the interface coupling held before.
  double continuation_energy() const { return continuation_energy_; }
  /// An upper bound of the largest eigenvalue of M^-1 K_s, K_s the faces' springs at K0 on every
  /// `eligible` interior edge, M the pair masses (the fully split map's; merged nodes only lower
  /// it). Gershgorin on M^-1/2 K_s M^-1/2. Adding it to the cells' bound (StableTimeStep)
  /// bounds the whole system's eigenvalue, since lambda_max(A + B) <= lambda_max(A) +
  /// lambda_max(B).
  /// With friction the stick spring adds the closure stiffness to the shear; a closure stiffer
  /// than K0 sets the normal spring.
  static double eigenvalue_bound(const PolygonMesh& mesh, const LumpedMass& mass,
                                 const CohesiveLaw& law, const std::vector<char>& eligible,
                                 double friction = 0.0, const ClosureStiffness& closure = {});
  /// The springs of every `eligible` interior edge at their stiffest (the one stiffness of
  /// eigenvalue_bound, in both directions), assembled on `dofs`: K_s with u.K_s u / 2 the
  /// springs' energy. On a map split along every eligible edge, the cells' K plus K_s has the
  /// largest eigenvalue (over M) of every crack pattern a run can reach: a pattern's map is
  /// this one with the uncracked faces' jumps held at zero, where their springs store nothing,
  /// so its Rayleigh quotients are some of this system's; the law's tangent on a cracked face
  /// is below the stiffest spring.
  static Eigen::SparseMatrix<double> spring_stiffness(const PolygonMesh& mesh,
                                                      const SplitDofMap& dofs,
                                                      const CohesiveLaw& law,
                                                      const std::vector<char>& eligible,
                                                      double friction = 0.0,
                                                      const ClosureStiffness& closure = {});
  /// safety x the critical step of the cells (`cells`, the cell-by-cell bound, valid for every
  /// split) and the springs together: stable for every crack pattern a run can reach.
  static double stable_step(const StableTimeStep& cells, const PolygonMesh& mesh,
                            const LumpedMass& mass, const CohesiveLaw& law,
                            const std::vector<char>& eligible, double safety, double friction = 0.0,
                            const ClosureStiffness& closure = {});
  /// The cracked edges, in the order they cracked.
  const std::vector<int>& edges() const { return edges_; }
  bool cracked(int e) const { return slot_[e] >= 0; }

  // What CentralDifference calls.
  /// Takes the nodes of the cracked edges' ends from a DOF map (again after a remap or a new edge).
  void bind(const SplitDofMap& dofs);
  /// bind for the faces at the listed mesh vertices alone: after a split
  /// (SplitDofMap::disconnect), the re-classed vertices, which include every new face's ends.
  void rebind(const SplitDofMap& dofs, std::span<const int> vertices);
  /// Adds to f (node DOFs of the bound map) the cohesive forces at node displacements u,
  /// advances the points' histories and books the work since the last evaluation.
  void evaluate(const Eigen::VectorXd& u, Eigen::VectorXd& f);
  /// Adds to f the forces of the last evaluation, onto the nodes of the map bound now: what
  /// evaluate would add at unchanged openings (after a split, which copies the displacements),
  /// bit for bit, without re-running the law or booking work.
  void reassemble(Eigen::VectorXd& f) const;

  /// Work of the cohesive tractions on the body so far (<= 0 up to the discretization error).
  double work() const { return work_; }
  /// The law's closed forms over the cracked edges (per unit thickness): dissipated energy, sum
  /// of w G(delta_max), and the energy stored on the unloading lines and in the overclosure
  /// penalty at the last evaluation.
  double dissipated_energy() const;
  /// The same for cracked edge e alone (0 if not cracked).
  double dissipated_energy(int e) const;
  double stored_energy() const;
  /// The energy friction has dissipated on the faces (per unit thickness): sum of w mu p |slip
  /// increment|, the closed form beside work().
  double friction_dissipated_energy() const;
  /// Per mesh edge, the mean largest effective opening of its two points (0 if not cracked).
  Eigen::VectorXd max_openings() const;
  /// The traction (normal, tangential) at Gauss point q (from v0) of cracked edge e, at the
  /// last evaluation (or as it started). Throws InputError if e is not cracked.
  Eigen::Vector2d point_traction(int e, int q) const;
  /// Whether cracked edge e is fully broken: both its points past the critical opening.
  bool broken(int e) const;
  int num_broken() const;
  /// Whether cracked edge e may let go now (see Release above); false if it already has.
  bool releasable(int e) const;
  /// Edge e lets go: no more forces, its energies frozen (both zero). Throws InputError unless
  /// releasable(e).
  void release(int e);
  /// The released edges, in the order they let go.
  const std::vector<int>& released_edges() const { return released_; }

  /// Saves or loads every face with its points' histories, and the accounts (a checkpoint).
  void archive(StateArchive& a);

 private:
  struct QuadraturePoint {
    CohesiveLaw::State history;
    FrictionState friction;
    Eigen::Vector2d opening = Eigen::Vector2d::Zero();  // (normal, tangential), last evaluation
    Eigen::Vector2d traction = Eigen::Vector2d::Zero();
    Eigen::Vector2d jump = Eigen::Vector2d::Zero();   // u_cell1 - u_cell0, global, last evaluation
    Eigen::Vector2d force = Eigen::Vector2d::Zero();  // w (tau_n n + tau_t t), global, on cell1
    Eigen::Vector2d shift = Eigen::Vector2d::Zero();  // law opening - face-frame jump (add_edge)
  };
  struct Face {
    int edge;
    std::array<int, 2> side0, side1;  // (cell, local vertex) of v0 then v1 on each side
    std::array<int, 2> node0{-1, -1}, node1{-1, -1};  // bound nodes of v0, v1 on each side
    Eigen::Vector2d n, t;
    double length;
    double closure;  // the overclosure penalty's stiffness k
    std::array<QuadraturePoint, 2> points;
    double end_gap = 0.0;  // the smaller of the two end jumps' lengths, last evaluation
    bool released = false;
    // Turning frames: the chord d between the mean ends at the last evaluation, and the force
    // dE/dd the face's energy puts on it (see frame_force); none before the first evaluation.
    Eigen::Vector2d chord = Eigen::Vector2d::Zero(), chord_force = Eigen::Vector2d::Zero();
    bool framed = false;
  };
  /// A face's frame now: its normal and tangent, and (turning) the chord they follow.
  struct Frame {
    Eigen::Vector2d n, t, chord;
    double length = 0.0;  // |chord|; 0: the reference frame
  };
  static Face make_face(const PolygonMesh& mesh, int e);
  /// Edge e's face spring at its stiffest: K0, the closure, or the shear with the stick spring.
  static double stiffest_spring(const CohesiveLaw& law, int e, double friction,
                                const ClosureStiffness& closure);
  /// The face's (n, t) now: the reference ones, or with turning frames those of the line
  /// through the mean positions of its two sides' ends.
  Frame frame(const Face& face, const Eigen::VectorXd& u) const;
  /// Spreads a chord force over the face's ends: -1/2 of it on both sides' v1 nodes, +1/2 on
  /// their v0 nodes (the chord runs between the mean positions of v0 and v1).
  static void add_chord_force(const Face& face, const Eigen::Vector2d& force, Eigen::VectorXd& f);
  /// Spreads point q's force (global, the one cell1's side takes with a minus) over the face's
  /// four bound nodes.
  static void add_point_force(const Face& face, int q, const Eigen::Vector2d& force,
                              Eigen::VectorXd& f);
  ClosureStiffness closure_;
  double friction_ = 0.0;  // Coulomb's mu on closed faces
  bool turning_ = false;   // the faces' frames turn with them
  /// The law of face `slot` (the shared one unless the strength varies).
  const CohesiveLaw& law_of(std::size_t slot) const {
    return face_laws_.empty() ? law_ : face_laws_[slot];
  }
  /// The nodes of face f's ends on both sides.
  void bind_face(const SplitDofMap& dofs, Face& f) const;
  /// The law with edge e's strength (a varying strength).
  CohesiveLaw edge_law(int e) const;

  const PolygonMesh& mesh_;
  const CohesiveLaw& law_;
  std::vector<double> edge_strength_;   // per edge; empty: uniform
  std::vector<CohesiveLaw> face_laws_;  // per face when the strength varies
  std::vector<Face> faces_;
  std::vector<int> edges_;
  std::vector<int> slot_;  // per mesh edge: its face, or -1
  std::vector<int> released_;
  double work_ = 0.0;
  double continuation_energy_ = 0.0;
  /// The point of the law's elastic branch (the closure k in compression) carrying `traction`.
  static Eigen::Vector2d carrying_opening(const CohesiveLaw& law, double k,
                                          const Eigen::Vector2d& traction);
};

}  // namespace vorodg
