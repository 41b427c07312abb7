#pragma once
// The mesh of an explicit run: one mesh per body joined into one PolygonMesh, because contact
// between bodies is contact between the surface cells of one mesh. The bodies share no vertex,
// so no cell of one is a neighbour of a cell of the other and the element layer sees them as
// separate (a weight function's patch never crosses between them).
#include <vector>

#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

struct BodiesMesh {
  PolygonMesh mesh;  // its domain is the bounding box of the bodies
  /// Body b owns cells [first_cell[b], first_cell[b + 1]) and their vertices.
  std::vector<int> first_cell;
  int body_of_cell(int c) const;
  /// sqrt(area of the bodies / cells): the mesh's h_avg, without the space between bodies.
  double h_avg = 0.0;
};

}  // namespace vorodg
