#pragma once
// Cells whose shape functions are the same up to a translation, so that an element table
// computes them once per class (as deal.II's FEValues does for a mesh of equal cells). A cell's
// RK shape functions depend on its own polygon and, through the vertex weight functions (solved
// on each vertex's patch), on every cell that shares a vertex with it and on which of those
// edges lie on the domain's boundary. Two cells are congruent when that whole neighbourhood is
// the same polygon set after moving one cell's centroid onto the other's: compared coordinate by
// coordinate, relative to the cell's size, within `tolerance`. Nothing about the mesh family is
// assumed: an rcp mesh has (almost) no congruent cells and costs one key per cell to find that
// out; every interior cell of a quad or hexagon grid falls into one class.
//
// A member of a class takes its representative's values: they differ from its own by the
// effect of a change of its geometry within the tolerance (1e-11 of the cell's size by default)
// plus the round-off of the patch solves' summation order, far below any digit a report prints
// (docs/performance.md, "Congruent cells").
#include <vector>

#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

class CongruentCells {
 public:
  static constexpr double kDefaultTolerance = 1e-11;
  explicit CongruentCells(const PolygonMesh& mesh, double tolerance = kDefaultTolerance);

  /// The first cell of c's class (c itself for a class of one, or a class's first member).
  int representative(int c) const { return representative_[c]; }
  int num_classes() const { return classes_; }
  /// Cells in c's class.
  int class_size(int c) const { return size_[representative_[c]]; }

 private:
  std::vector<int> representative_;
  std::vector<int> size_;  // per representative: its class's size (0 for members)
  int classes_ = 0;
};

}  // namespace vorodg
