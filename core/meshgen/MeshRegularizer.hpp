#pragma once
// Small-edge regularization (report section 2, Figure 4): edges shorter than a threshold are
// collapsed and their end vertices merged, shortest first and recursively, as long as no cell is
// inverted, emptied, made self-intersecting or non-star-shaped about its centroid. Corners of the
// domain never move; vertices on a side stay on it. Cells left with fewer than `min_sides` sides
// (triangles cut off by a side, or made by a collapse) are then merged into a neighbour, so that
// every cell has 4 to 8 sides as in the report's Figure 4.
#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

struct RegularizationResult {
  PolygonMesh mesh;
  int collapsed_edges = 0;
  int refused_collapses = 0;  // short edges that could not be collapsed safely
  int merged_cells = 0;       // cells with too few sides merged into a neighbour
};

/// Collapses every edge shorter than `threshold` that can be collapsed safely, then merges cells
/// with fewer than `min_sides` sides into the neighbour that gives a valid cell with the fewest
/// sides (at most `max_sides`). A threshold of 0 returns the mesh unchanged.
RegularizationResult regularize_mesh(const PolygonMesh& mesh, double threshold, int min_sides = 4,
                                     int max_sides = 8);

/// The second step alone: merges cells with fewer than `min_sides` sides into a neighbour.
/// Returns the new mesh and the number of merges through `merged`.
PolygonMesh merge_small_cells(const PolygonMesh& mesh, int min_sides, int max_sides, int& merged);

}  // namespace vorodg
