#pragma once
// Contact between the surface cells of one mesh (all bodies and fragments live in it), one step
// at a time: the current bounding box of every surface cell, the pairs whose boxes overlap and
// that are not neighbours (ContactCandidates: a grid search with a skin, kept while nothing has
// moved by the skin; cells that share a mesh vertex are never tested, SurfaceCells), both passes of
// vertex-in-polygon (A's vertices in B, then B's in A) and the penalty law.
//
// A node seen by several of its pairs counts once: a body's vertex is a pair of each cell around
// it, and when it is inside a cell B, every surface cell of its that is a candidate with B finds
// it. The first finding (in the deterministic order of the search) takes the contact, keyed by
// (node, B); the others are skipped. Without this, a vertex shared by two surface cells would be
// pushed twice as hard, and the mass-scaled stiffness would lose its stability margin.
//
// A vertex found inside a cell for the first time should be there by one step's motion: its
// depth is at most its approach speed times dt (central differences move it by dt v_half, and v
// is that v_half). A vertex found deeper got in unseen: through a cell the neighbour filter
// hides from it, or before a crack made its target a surface cell, or before a released face let
// its two cells see each other. Pushing it out from that depth would make k d^2 / 2 of energy
// from nothing (measured: a tenth of a cell's size is 10^3 times the input energy of a falling
// column; a twentieth, 6 % of it). Two cases:
//  - Late contacts: first found deeper than kReachSlack times the step's approach, yet within
//    SurfaceSearch::kTunnelDepth of the cell's size. The law acts on the depth beyond the one it
//    was found at (the offset), so the contact stops it going deeper and stores nothing it was not
//    given. The offset shrinks as the vertex backs out (it is the least depth seen), and the
//    contact is forgotten once the vertex is out. The report counts them (`late`, `new_late`).
//  - Tunnelled vertices: first found deeper than SurfaceSearch::kTunnelDepth of the cell's size.
//  Such a vertex
//    is deep in the body, where the nearest exit says little about how it got there, so it gets
//    no force for as long as it stays inside (`tunnelled`, `new_tunnels`).
// Without velocities in the state every first finding within kTunnelDepth is taken as it is.
// Penetrations are tracked from one evaluation to the next by (pair, target cell), which a remap
// does not change; so is the shear of friction (ContactFriction), which a contact carries from
// step to step and forgets when it ends.
#include <cstdint>
#include <optional>
#include <span>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "dynamics/contact/ContactCandidates.hpp"
#include "dynamics/contact/ContactFriction.hpp"
#include "dynamics/contact/ContactLaw.hpp"
#include "dynamics/contact/ContactReport.hpp"
#include "dynamics/contact/PairState.hpp"
#include "dynamics/contact/PenaltyContact.hpp"
#include "dynamics/contact/SurfaceCells.hpp"
#include "dynamics/contact/SurfaceSearch.hpp"

namespace vorodg {

class StateArchive;

class SurfaceContact final : public ContactLaw {
 public:
  /// grid_spacing > 0 is the grid's smallest spacing: the mesh's h_avg is the natural choice
  /// (the search raises it to the largest surface-cell box each step).
  SurfaceContact(const PenaltyContact& law, double grid_spacing,
                 const ContactFriction& friction = ContactFriction{});

  /// Adds the contact forces between surface cells to `force` (one entry per pair, the mesh's
  /// CSR layout; the integrator sums the pairs of each node) and reports the step.
  /// Throws InputError if `state` lacks what the law needs, NumericalError if a surface cell
  /// has non-finite vertex positions.
  /// The velocity penalty's part of the forces goes to `velocity_force` too, if not empty.
  ContactReport add_forces(const SurfaceCells& surface, const PairState& state,
                           std::span<Point> force, std::span<Point> velocity_force = {}) override;
  /// Equal and opposite forces between parts of the mesh.
  bool external() const override { return false; }

  /// Only the search: the cell pairs (mesh cell ids, the first earlier in the surface order)
  /// whose current boxes overlap and that are not neighbours, each once, in a fixed order (by
  /// place in the surface order, first then second). These are what add_forces tests.
  const std::vector<IndexPair>& find_pairs(const SurfaceCells& surface,
                                           std::span<const Point> position) {
    return search_.find(surface, position);
  }
  const std::vector<IndexPair>& cell_pairs() const { return search_.cell_pairs(); }
  /// The pairs the last add_forces gave a force (each contact's vertex and edge ends, in the
  /// order it pushed them; with repeats).
  std::span<const int> touched() const override { return touched_; }

  const PenaltyContact& law() const { return law_; }
  const ContactFriction& friction() const { return friction_; }
  const ContactCandidates& candidates() const { return search_.candidates(); }

  void archive(StateArchive& a) override;

 private:
  /// Pushes the vertices of surface cell i out of surface cell j (indices in surface order).
  void test_pass(const SurfaceCells& surface, int i, int j, const PairState& state,
                 std::span<Point> force, std::span<Point> velocity_force, ContactReport& report);
  /// The depth the law acts on for the penetration `key` ((pair, target cell)) found at
  /// `depth` into cell b, whose first finding could have reached `reach`: beyond its offset, or
  /// none if it is a tunnelled one (see above). Records it for the next evaluation either way.
  struct Acting {
    double depth = 0.0;  // what the law acts on
    double shear = 0.0;  // the friction shear carried from the last evaluation
  };
  std::optional<Acting> acting_depth(std::uint64_t key, double depth, double reach,
                                     const PolygonMesh& mesh, int b, ContactReport& report);
  /// Friction on the contact `key` of pair p in the edge (e0, e1), pushed with `normal` of
  /// stiffness k: adds the shear's forces and records the shear for the next evaluation.
  void add_friction(std::uint64_t key, const Penetration& pen, int p, int e0, int e1,
                    const PenaltyContact::Response& normal, double previous_shear,
                    const PairState& state, std::span<Point> force, ContactReport& report);

  /// A first depth beyond this multiple of the step's approach (|v_n| dt) is a late contact.
  /// 2 leaves room for the target edge turning and bending within the step.
  static constexpr double kReachSlack = 2.0;

  PenaltyContact law_;
  ContactFriction friction_;
  SurfaceSearch search_;
  std::unordered_set<std::uint64_t> taken_;  // (node, target cell) keys of this step
  std::vector<int> touched_;
  // (pair, target cell) keys of the penetrations found at the last evaluation and at this one:
  // those that got a force, with their offsets and friction shears, and those left alone as
  // tunnelled.
  struct Tracked {
    double offset = 0.0;
    double shear = 0.0;
  };
  std::unordered_map<std::uint64_t, Tracked> inside_, inside_next_;
  std::unordered_set<std::uint64_t> tunnelled_, tunnelled_next_;
};

}  // namespace vorodg
