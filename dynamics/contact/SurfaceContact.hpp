#pragma once
// Contact between the surface cells of one mesh (all bodies and fragments live in it), one step
// at a time: the current bounding box of every surface cell, the grid search for overlapping
// boxes, the neighbour filter (cells that share a mesh vertex are never tested, SurfaceCells),
// both passes of vertex-in-polygon (A's vertices in B, then B's in A) and the penalty law.
//
// A node seen by several of its pairs counts once: a body's vertex is a pair of each cell around
// it, and when it is inside a cell B, every surface cell of its that is a candidate with B finds
// it. The first finding (in the deterministic order of the search) takes the contact, keyed by
// (node, B); the others are skipped. Without this, a vertex shared by two surface cells would be
// pushed twice as hard, and the mass-scaled stiffness would lose its stability margin.
//
// Tunnelled vertices are left alone. A vertex enters a cell at a depth of about one step's
// motion, far below a tenth of the cell's size unless the two move apart at a good fraction of
// the wave speed. A vertex first found deeper than that (kTunnelDepth) got in unseen: through a
// cell the neighbour filter hides from it, or before a crack made the cell a surface cell. The
// penalty would push it out with k d^2 / 2 of energy made from nothing (a tenth of the cell's
// size is 10^3 times the input energy of a falling column, measured). So it gets no force, for
// as long as it stays inside; the report counts it (`tunnelled`, `new_tunnels`). Penetrations are
// tracked from one evaluation to the next by (pair, target cell), which a remap does not change.
#include <cstdint>
#include <span>
#include <unordered_set>
#include <vector>

#include "dynamics/contact/ContactGrid.hpp"
#include "dynamics/contact/ContactReport.hpp"
#include "dynamics/contact/PairState.hpp"
#include "dynamics/contact/PenaltyContact.hpp"
#include "dynamics/contact/SurfaceCells.hpp"

namespace vorodg {

class SurfaceContact {
 public:
  /// grid_spacing > 0 is the grid's smallest spacing: the mesh's h_avg is the natural choice
  /// (the search raises it to the largest surface-cell box each step).
  SurfaceContact(const PenaltyContact& law, double grid_spacing);

  /// Adds the contact forces between surface cells to `force` (one entry per pair, the mesh's
  /// CSR layout; the integrator sums the pairs of each node) and reports the step.
  /// Throws InputError if `state` lacks what the law needs, NumericalError if a surface cell
  /// has non-finite vertex positions.
  ContactReport add_forces(const SurfaceCells& surface, const PairState& state,
                           std::span<Point> force);

  /// Only the search: the cell pairs (mesh cell ids, the first earlier in the surface order)
  /// whose current boxes overlap and that are not neighbours, each once, in a deterministic
  /// order. These are what add_forces tests.
  const std::vector<IndexPair>& find_pairs(const SurfaceCells& surface,
                                           std::span<const Point> position);
  const std::vector<IndexPair>& cell_pairs() const { return cell_pairs_; }

  const PenaltyContact& law() const { return law_; }
  const ContactGrid& grid() const { return grid_; }

 private:
  /// Pushes the vertices of surface cell i out of surface cell j (indices in surface order).
  void test_pass(const SurfaceCells& surface, int i, int j, const PairState& state,
                 std::span<Point> force, ContactReport& report);
  /// Whether the penetration `key` ((pair, target cell)) at `depth` into cell b is a tunnelled
  /// one (see above); records it for the next evaluation either way.
  bool tunnelled(std::uint64_t key, double depth, const PolygonMesh& mesh, int b,
                 ContactReport& report);

  /// A first depth beyond this fraction of the target's size (the root of its reference area)
  /// is a tunnelled vertex.
  static constexpr double kTunnelDepth = 0.1;

  PenaltyContact law_;
  ContactGrid grid_;
  std::vector<Box> boxes_;                   // per surface cell, in surface order
  std::vector<IndexPair> surface_pairs_;     // the same pairs, by index in surface order
  std::vector<IndexPair> cell_pairs_;        // mesh cell ids
  std::unordered_set<std::uint64_t> taken_;  // (node, target cell) keys of this step
  // (pair, target cell) keys of the penetrations found at the last evaluation and at this one:
  // those that got a force, and those left alone as tunnelled.
  std::unordered_set<std::uint64_t> inside_, inside_next_, tunnelled_, tunnelled_next_;
};

}  // namespace vorodg
