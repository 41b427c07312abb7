#pragma once
// Rebuilding a mesh from new cell loops: without the vertices no loop uses (compact_mesh), and
// with vertices that sit at one position merged (merge_coincident_vertices).
#include <span>
#include <vector>

#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

/// The mesh of `loops` (cells in this order) over `positions`, like `like` in domain and tagging,
/// without the vertices no loop uses. Vertices keep their relative input order, which keeps
/// generation deterministic.
PolygonMesh compact_mesh(const PolygonMesh& like, std::span<const Point> positions,
                         const std::vector<std::span<const int>>& loops);

/// Merges the two ends of every edge not longer than `tol` (the survivor keeps the smaller id's
/// position) and drops the repeated vertex from the loops. A Voronoi vertex of four or more
/// nearly co-circular seeds comes out as two vertices a round-off apart, joined by an edge of no
/// length; the tessellator merges them within 1e-9 of the spacing, and this catches the ones the
/// mesh validator would still call duplicates. `merged` counts the vertices removed.
PolygonMesh merge_coincident_vertices(const PolygonMesh& mesh, double tol, int& merged);

}  // namespace vorodg
