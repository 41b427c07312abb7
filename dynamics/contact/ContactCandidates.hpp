#pragma once
// The broad phase of surface contact, kept from step to step (a Verlet list): which pairs of
// surface cells, not neighbours, have overlapping current bounding boxes.
//
// The grid search (ContactGrid) and the neighbour filter (SurfaceCells::neighbours) run only
// when the list is rebuilt, on the boxes inflated by a skin s on every side. The list is kept
// while no vertex of a surface cell has moved more than s from where it was at the rebuild, and
// while the surface cells and their released edges are the same (SurfaceCells::revision). Then
// every pair whose current boxes overlap is in it: each current box lies within its cell's box
// at the rebuild grown by the largest move, so two current boxes that overlap had inflated
// boxes that overlapped. Each step the kept pairs are tested against the current boxes, so the
// result is exactly the pairs the search would find that step, in a fixed order (by surface
// index, first then second).
//
// The skin is kSkin times the grid's smallest spacing (the mesh's h_avg): on the column at h = 4
// the vertices move about 7 um a step against a skin of 2.5 mm, so the list lasts hundreds of
// steps, and the pairs it adds are cheap rejects of the box test.
#include <span>
#include <vector>

#include "dynamics/contact/ContactGrid.hpp"
#include "dynamics/contact/SurfaceCells.hpp"

namespace vorodg {

class StateArchive;

class ContactCandidates {
 public:
  /// min_spacing > 0: the grid's smallest spacing. Throws InputError.
  explicit ContactCandidates(double min_spacing);

  /// The pairs (indices in surface order, first < second) of surface cells that are not
  /// neighbours and whose `boxes` (the current box of each surface cell, in surface order)
  /// overlap. `position` holds every (cell, vertex) pair's current position (the mesh's CSR
  /// layout). The result lives until the next call.
  const std::vector<IndexPair>& overlapping(const SurfaceCells& surface,
                                            std::span<const Point> position,
                                            std::span<const Box> boxes);

  /// How many times the list was built, and how many calls there were.
  long rebuilds() const { return rebuilds_; }
  long calls() const { return calls_; }
  const ContactGrid& grid() const { return grid_; }

  /// The skin, as a fraction of the grid's smallest spacing.
  static constexpr double kSkin = 0.1;

  /// Saves or loads the list with the positions it was built at (a checkpoint: a list rebuilt
  /// at another moment could hold other pairs, in another order).
  void archive(StateArchive& a);

 private:
  bool stale(const SurfaceCells& surface, std::span<const Point> position) const;
  void rebuild(const SurfaceCells& surface, std::span<const Point> position,
               std::span<const Box> boxes);

  ContactGrid grid_;
  double skin_;
  const SurfaceCells* surface_ = nullptr;  // what the list was built for
  long revision_ = -1;
  std::vector<Point> snapshot_;        // per (cell, vertex) pair: its position at the rebuild
  std::vector<Box> inflated_;          // per surface cell, at the rebuild
  std::vector<IndexPair> candidates_;  // sorted by (first, second)
  std::vector<IndexPair> overlapping_;
  long rebuilds_ = 0, calls_ = 0;
};

}  // namespace vorodg
