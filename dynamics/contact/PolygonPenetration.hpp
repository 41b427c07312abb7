#pragma once
// The narrow phase of contact between two cells: which vertices of polygon A lie inside polygon B,
// how deep, and where on B's boundary the reaction goes (node-to-face contact; call it twice with
// the roles swapped for the symmetric, two-pass test).
//
// For a vertex p inside B, q is the point of B's boundary closest to p, on edge k of B at
// parameter t: q = (1 - t) b_k + t b_k+1. The depth is d = |q - p| and the normal n = (q - p) / d
// points out of B. The penalty force F n on p and -F n on q, the latter split (1 - t, t) over the
// edge's two ends, sum to zero, and their moment vanishes because the force acts along q - p.
// This split is also the exact gradient of d with respect to the edge's ends, so the force
// derives from the potential k d^2 / 2.
//
// Limits:
//   - Inside is the even-odd rule, right for any simple polygon, convex or not. The closest
//     point is exact for any simple polygon too: at a reflex vertex of B, q is the vertex (t = 0
//     or 1) and n points from p to it.
//   - Only vertices are tested: two slender cells crossing like an X, with no vertex inside the
//     other, are missed. With steps that move a vertex a small fraction of a cell per step, and
//     penalties that keep penetrations small, a vertex always enters first.
//   - The closest edge is the right exit while the depth is below about half of B's inradius.
//     Deeper, p may be pushed out through the far side. The mass-scaled penalty of PenaltyContact
//     keeps the depth near a few steps' worth of motion.
//   - Exits: when B has exposed edges (SurfaceCells), only those are candidate exits, so that p
//     is pushed out of B's body rather than into the neighbour across a bonded edge.
#include <optional>
#include <span>
#include <vector>

#include "core/geometry/Rectangle.hpp"

namespace vorodg {

/// A vertex of one polygon inside another.
struct Penetration {
  int vertex = -1;  // local index of the penetrating vertex in its own polygon
  int edge = -1;    // local edge k of the penetrated polygon, from its vertex k to k + 1
  double t = 0.0;   // q = (1 - t) b_k + t b_k+1, t in [0, 1]
  double depth = 0.0;
  Point normal = Point::Zero();  // unit, out of the penetrated polygon at q
};

class PolygonPenetration {
 public:
  /// Whether p lies inside the loop (even-odd crossing rule). Points on the boundary may go
  /// either way; there the depth is zero and the force with it.
  static bool inside(const Point& p, std::span<const Point> loop);

  /// p's penetration into polygon b: empty if p is not inside, or touches (a depth below 1e-12
  /// of the edge's length: on the boundary up to round-off). `exits` (one flag per edge of b, or
  /// empty for all edges) says which edges p may leave through.
  static std::optional<Penetration> of_point(const Point& p, std::span<const Point> b,
                                             std::span<const char> exits);

  /// Appends the penetration of every vertex of a into b, in vertex order.
  static void vertices_inside(std::span<const Point> a, std::span<const Point> b,
                              std::span<const char> exits_b, std::vector<Penetration>& out);
};

}  // namespace vorodg
