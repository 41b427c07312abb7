#pragma once
// Extrinsic dynamic fracture (report sections 4 and 6): after every step of the integrator, the
// intact edges that fail the Mohr-Coulomb criterion crack (CrackInsertion); the DOF map is
// rebuilt bottom-up from the equivalence classes of (cell, vertex) pairs across the uncracked
// edges (SplitDofMap), the integrator is remapped onto it (each split node's halves keep its
// displacement and velocity with their own pairs' masses, so mass and momentum are kept), and
// the cohesive law acts on the new faces from zero opening (CohesiveForces).
//
// An edge that cracks alone inside the body splits no node: its ends are still joined around
// the vertex through the other edges, so it cannot open until a neighbouring edge cracks too.
// It stays cracked and opens then, as the report's node-splitting scheme implies.
//
// Release. After each step, a cracked face that may let go (CohesiveForces::releasable: broken,
// open, its ends apart by its length) and whose two cells do not overlap is released: the
// cohesive forces stop, and surface contact tests its two cells against each other from then
// on. Without surface contact no face is released: the closure penalty is then all that keeps
// crack faces apart.
//
// Interfaces coupled from the start (set_activation): the run's map has split the edges that may
// crack from t = 0 and the interior-penalty coupling holds them; the check is then
// InterfaceActivation's, on the consistent interface traction, and a failing edge leaves the
// coupling for a cohesive face that continues from the traction it carried, with no remap (its
// nodes are split already). Release is the same.
//
// One insertion pass per step: a split copies the displacements, so the cells' stresses, and
// with them every utilization, are the same after it; nothing more fails at that instant.
#include <span>
#include <vector>

#include "dynamics/CentralDifference.hpp"
#include "dynamics/CohesiveForces.hpp"
#include "dynamics/CrackInsertion.hpp"
#include "dynamics/InterfaceActivation.hpp"
#include "fracture/CrackHistory.hpp"
#include "fracture/CrackState.hpp"

namespace vorodg {

class StateArchive;

class DynamicFracture {
 public:
  /// Sets `cohesive` on `run`. Every argument must outlive this object. With `contact` (the
  /// run's), each cracked edge is exposed as free surface, so that pieces that come apart
  /// touch again through surface contact.
  DynamicFracture(const PolygonMesh& mesh, CentralDifference& run, CohesiveForces& cohesive,
                  const CrackInsertion& insertion, ContactForces* contact = nullptr);

  /// Interfaces coupled from the start: `activation` (on the run's coupling) replaces the
  /// insertion check. Must outlive this object; set before the first step.
  void set_activation(InterfaceActivation& activation) { activation_ = &activation; }

  /// Interior edges split from the start that carry no force (a notch): never joined by a
  /// rebuilt map, never cracked. The run's map must be split along them already. Call before
  /// the first step.
  void cut(std::span<const int> edges);

  /// One step of the integrator, then the insertion check; returns the edges cracked after it.
  int step(int threads);

  using Event = CrackEvent;
  /// Every crack in the order it formed (the step after which it did).
  const std::vector<Event>& events() const { return events_; }
  /// Per mesh edge: 1 if cracked.
  const std::vector<char>& cracked() const { return cracked_; }
  /// The cracked edges with their mean largest openings.
  CrackState crack_state() const;
  /// Only the fully broken edges (both points past the critical opening): what separates
  /// fragments, since a cohesive edge still holds its faces together.
  CrackState broken_state() const;

  /// Wall seconds so far in each part of step(): the integrator's step with the faces'
  /// release, the insertion check, and the rebuild after cracks (new faces, the split map and
  /// the remap). What docs/performance.md quotes as the check's and the rebuild's share.
  struct Times {
    double integrator = 0.0, check = 0.0, rebuild = 0.0;
  };
  const Times& times() const { return times_; }

  /// Saves or loads which edges cracked, in which order, and the map's edge set (a checkpoint;
  /// the run's map itself is the integrator's).
  void archive(StateArchive& a);

 private:
  /// Releases the faces that may let go (see Release above).
  void release_faces();
  /// The check and the rebuild of the coupled-interface approach; returns the edges activated.
  int activate(int threads);
  /// Marks `edge` cracked, exposes it to contact and logs it.
  void crack(int edge);

  const PolygonMesh& mesh_;
  CentralDifference& run_;
  CohesiveForces& cohesive_;
  const CrackInsertion& insertion_;
  ContactForces* contact_;
  InterfaceActivation* activation_ = nullptr;
  std::vector<char> cracked_;
  std::vector<char> connected_;  // !cracked_: the edge set of the DOF map
  bool split_yet_ = false;       // whether the run's map was built from connected_
  std::vector<Event> events_;
  Times times_;
};

}  // namespace vorodg
