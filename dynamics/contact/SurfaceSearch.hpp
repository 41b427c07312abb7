#pragma once
// The broad phase of contact between the surface cells of one mesh, shared by the penalty law
// (SurfaceContact, at the current positions) and the exact one (ExactSurfaceContact, at the
// predicted next positions): every surface cell's bounding box at the given positions, and the
// pairs of cells whose boxes overlap and that are not neighbours (ContactCandidates: a grid
// search with a skin; cells that share a mesh vertex are never tested, SurfaceCells).
#include <span>
#include <vector>

#include "dynamics/contact/ContactCandidates.hpp"
#include "dynamics/contact/SurfaceCells.hpp"

namespace vorodg {

class StateArchive;

class SurfaceSearch {
 public:
  /// grid_spacing > 0: the grid's smallest spacing (the mesh's h_avg is the natural choice).
  explicit SurfaceSearch(double grid_spacing) : candidates_(grid_spacing) {}

  /// The cell pairs (mesh cell ids, the first earlier in the surface order) whose boxes at
  /// `position` (one per (cell, vertex) pair) overlap and that are not neighbours, each once,
  /// in a fixed order. Throws InputError for a wrong number of positions, NumericalError naming
  /// the cell for a non-finite one.
  const std::vector<IndexPair>& find(const SurfaceCells& surface, std::span<const Point> position);
  /// The same pairs as indices into the surface order, and the boxes of the last find().
  const std::vector<IndexPair>& surface_pairs() const { return *surface_pairs_; }
  const std::vector<IndexPair>& cell_pairs() const { return cell_pairs_; }
  const Box& box(int surface_index) const { return boxes_[surface_index]; }
  const ContactCandidates& candidates() const { return candidates_; }

  /// Cell c's loop of positions, from the per-pair positions.
  static std::span<const Point> loop(const PolygonMesh& mesh, std::span<const Point> position,
                                     int c) {
    return position.subspan(mesh.offsets()[c], mesh.cell_size(c));
  }

  /// A first depth beyond this fraction of the target's size (the root of its reference area) is
  /// a vertex that tunnelled in: the nearest exit says little about how it got there.
  static constexpr double kTunnelDepth = 0.1;

  /// Saves or loads the candidate list and the last evaluation's boxes and pairs (a checkpoint).
  void archive(StateArchive& a);

 private:
  ContactCandidates candidates_;
  std::vector<Box> boxes_;  // per surface cell, in surface order
  const std::vector<IndexPair>* surface_pairs_ = &none_;
  std::vector<IndexPair> cell_pairs_;
  std::vector<IndexPair> none_;
};

}  // namespace vorodg
