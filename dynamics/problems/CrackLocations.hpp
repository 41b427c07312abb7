#pragma once
// Where a body broke, for the column's ablation (docs/impact.md): the report describes
// fragmentation at the struck corner and bending cracks at mid-height. Each broken edge is
// placed by its midpoint in the reference configuration:
//   - near the impact: within one body width (the shorter side) of the impact point;
//   - mid-length: otherwise, in the middle third of the body's length along its long axis;
//   - elsewhere: the rest.
#include <vector>

#include "core/geometry/Rectangle.hpp"
#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

struct CrackLocations {
  // fractions of the broken edges (NaN each when there are none)
  double near_impact = 0.0, mid_length = 0.0, elsewhere = 0.0;
};

CrackLocations crack_locations(const PolygonMesh& mesh, const std::vector<int>& broken_edges,
                               const Rectangle& body, const Point& impact);

}  // namespace vorodg
