#pragma once
// Small polygon kernels shared by the mesh, its validity check, the generators and (later) the
// element layer's fan quadrature. A polygon is a loop of points; counter-clockwise is positive.
#include <Eigen/Core>
#include <span>
#include <vector>

#include "core/geometry/Rectangle.hpp"

namespace vorodg::polygon {

/// Twice the signed area of triangle (a, b, c): > 0 when counter-clockwise.
inline double orient2(const Point& a, const Point& b, const Point& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

/// Signed area (shoelace), positive for counter-clockwise loops. Coordinates are shifted by the
/// first vertex to keep the sum accurate far from the origin.
/// int psi_k n ds over a polygon's boundary for the hat function psi_k of a vertex (linear on its
/// two edges, zero on the others), from its neighbours `prev` and `next` in counter-clockwise
/// order: half the sum of (length x outward normal) of the two edges.
inline Eigen::Vector2d vertex_hat_flux(const Point& prev, const Point& next) {
  return {0.5 * (next.y() - prev.y()), 0.5 * (prev.x() - next.x())};
}

double signed_area(std::span<const Point> loop);
/// Area centroid; `area` must be signed_area(loop) and nonzero.
Point centroid(std::span<const Point> loop, double area);
/// True if two non-adjacent edges of the loop touch or cross (or a vertex repeats).
bool self_intersects(std::span<const Point> loop);
/// True if every fan triangle (c, v_i, v_i+1) is counter-clockwise with area above
/// `min_area`: the loop is star-shaped with respect to c (c lies in its kernel).
bool star_shaped_about(std::span<const Point> loop, const Point& c, double min_area);
/// Interior angle at vertex i of a counter-clockwise loop, in [0, 2 pi) radians.
double interior_angle(std::span<const Point> loop, std::size_t i);
/// Smallest interior angle in radians (reflex angles count as their interior value).
double min_interior_angle(std::span<const Point> loop);
/// Largest interior angle in radians.
double max_interior_angle(std::span<const Point> loop);
/// True if closed segments [p1,p2] and [q1,q2] share a point.
bool segments_intersect(const Point& p1, const Point& p2, const Point& q1, const Point& q2);
/// Distance from p to the segment [a, b].
double distance_to_segment(const Point& p, const Point& a, const Point& b);

}  // namespace vorodg::polygon
