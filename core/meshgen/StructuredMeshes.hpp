#pragma once
// Meshes with a lattice behind them: regular and randomly perturbed hexagons, and quadrilaterals.
#include <cstdint>

#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

/// Regular hexagons (Voronoi cells of a triangular lattice of spacing ~`spacing`) cut to the
/// rectangle. The spacing is adjusted so that a whole number of rows fits the height; the left,
/// bottom and top sides then cut through seeds or along edges. The right side does too when the
/// width is a multiple of the adjusted spacing (e.g. L/D = 8/sqrt(3) = 4.6188...).
PolygonMesh hex_mesh(const Rectangle& domain, double spacing);

/// Moves the vertices of `mesh` randomly, each by at most r x (its shortest edge): interior
/// vertices uniformly in a disk of that radius, side vertices uniformly along their side, corners
/// not at all. With r < 0.5 the two ends of an edge can never meet. On a hex mesh the bound is
/// r x (hexagon edge) except next to the half cells along the sides, whose edges are shorter.
PolygonMesh perturb_mesh(const PolygonMesh& mesh, double r, std::uint64_t seed);

/// Structured quadrilaterals with edge lengths close to h.
PolygonMesh quad_mesh(const Rectangle& domain, double h);

}  // namespace vorodg
