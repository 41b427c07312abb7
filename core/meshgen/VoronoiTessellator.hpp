#pragma once
// Seeds -> Delaunay triangulation (CGAL) -> Voronoi cells conforming to the rectangle.
// Conformity comes from reflecting the seeds near each side (and corner) across it: the bisector
// of a seed and its mirror image is the side itself, so the Voronoi cells of the original seeds
// tile the rectangle exactly. Vertices on the sides are snapped onto them, and Voronoi vertices
// that coincide (co-circular Delaunay pairs, which mirroring creates) are merged, so the raw
// tessellation has no zero-length edges.
#include <vector>

#include "core/geometry/Rectangle.hpp"
#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

/// Voronoi tessellation of `seeds` (all inside `domain`) clipped to the domain. Cell i belongs to
/// seeds[i]. `spacing` is the typical seed distance (d); seeds within 3 spacings of a side are
/// mirrored. Throws NumericalError if a cell cannot be closed (too few seeds for the domain).
PolygonMesh voronoi_mesh(const Rectangle& domain, const std::vector<Point>& seeds, double spacing);

/// Delaunay triangulation of `seeds` as a triangle mesh. The seeds must include the domain's
/// corners and enough points on its sides for the hull to be the rectangle.
PolygonMesh delaunay_mesh(const Rectangle& domain, const std::vector<Point>& seeds);

}  // namespace vorodg
