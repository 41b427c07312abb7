#pragma once
// Generalized barycentric coordinates of a polygon, the shape functions of the polygonal finite
// elements beside RK: Wachspress's (rational; convex polygons) and Floater's mean value
// coordinates (any simple polygon, so also the non-convex cells a regularized rcp mesh can have).
// Both sum to one, reproduce linear fields exactly and are linear on every edge, so the element
// conforms across shared edges and passes the patch test wherever its quadrature is exact for
// the stiffness (or the divergence correction makes it so).
#include <Eigen/Core>
#include <span>

namespace vorodg {

enum class BarycentricKind { wachspress, mean_value };

/// Values psi[k] and gradients grad[k] of the coordinates of the polygon `nodes`
/// (counter-clockwise, n >= 3) at a point x strictly inside it. The gradients are those of the
/// closed forms, differentiated exactly (forward mode), not by differences.
void barycentric_coordinates(BarycentricKind kind, std::span<const Eigen::Vector2d> nodes,
                             const Eigen::Vector2d& x, double* psi, Eigen::Vector2d* grad);

/// The first vertex (index into `nodes`) at which the polygon is not strictly convex (its
/// corner turns clockwise or not at all), or -1: Wachspress coordinates need strictly convex
/// polygons (at a straight corner that vertex's coordinate vanishes identically).
int first_non_convex_corner(std::span<const Eigen::Vector2d> nodes);

}  // namespace vorodg
