// Polygon kernels: signed area, centroid, self-intersection, star-shapedness, angles, segments.
#include "core/geometry/Polygon.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace vorodg {
namespace {

using Loop = std::vector<Point>;

Loop unit_square() {
  return {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)};
}

Loop reversed(Loop loop) {
  std::reverse(loop.begin(), loop.end());
  return loop;
}

Loop translated(Loop loop, const Point& t) {
  for (Point& p : loop) p += t;
  return loop;
}

// An arrow pointing right: a long thin shaft (x in [0,3], y in [0.4,0.6]) and a triangular head
// (x in [3,4]). Its kernel is the part of the head with x >= 3 and 0.4 <= y <= 0.6; its centroid
// (x ~ 2.33) lies in the shaft, outside the kernel.
Loop arrow() {
  return {Point(0, 0.4), Point(3, 0.4), Point(3, 0),  Point(4, 0.5),
          Point(3, 1),   Point(3, 0.6), Point(0, 0.6)};
}

TEST(Polygon, Orient2SignGivesTurnDirection) {
  EXPECT_GT(polygon::orient2(Point(0, 0), Point(1, 0), Point(0, 1)), 0.0);
  EXPECT_LT(polygon::orient2(Point(0, 0), Point(0, 1), Point(1, 0)), 0.0);
  EXPECT_EQ(polygon::orient2(Point(0, 0), Point(1, 1), Point(2, 2)), 0.0);
  EXPECT_DOUBLE_EQ(polygon::orient2(Point(0, 0), Point(2, 0), Point(0, 3)), 6.0);
}

TEST(Polygon, SignedAreaIsPositiveCounterClockwiseNegativeClockwise) {
  EXPECT_DOUBLE_EQ(polygon::signed_area(unit_square()), 1.0);
  EXPECT_DOUBLE_EQ(polygon::signed_area(reversed(unit_square())), -1.0);
  const Loop tri{Point(0, 0), Point(4, 0), Point(0, 3)};
  EXPECT_DOUBLE_EQ(polygon::signed_area(tri), 6.0);
  // Arrow: shaft 3 x 0.2 plus head 1 x 1 / 2.
  EXPECT_NEAR(polygon::signed_area(arrow()), 0.6 + 0.5, 1e-15);
  // Degenerate input.
  EXPECT_EQ(polygon::signed_area(Loop{Point(0, 0), Point(1, 1)}), 0.0);
  EXPECT_EQ(polygon::signed_area(Loop{Point(0, 0), Point(1, 1), Point(2, 2)}), 0.0);
}

TEST(Polygon, SignedAreaIsAccurateFarFromTheOrigin) {
  // A 1e-3 square at 1e6: a naive shoelace loses ~ 1e12 * eps ~ 1e-4 relative; shifting keeps it
  // near machine precision.
  const double s = 1e-3;
  const Loop far =
      translated({Point(0, 0), Point(s, 0), Point(s, s), Point(0, s)}, Point(1e6, 1e6));
  const double exact = (far[1].x() - far[0].x()) * (far[2].y() - far[1].y());
  EXPECT_NEAR(polygon::signed_area(far), exact, 1e-9 * exact);
}

TEST(Polygon, CentroidOfSquareTriangleAndArrow) {
  const Loop sq = unit_square();
  const Point c = polygon::centroid(sq, polygon::signed_area(sq));
  EXPECT_NEAR(c.x(), 0.5, 1e-15);
  EXPECT_NEAR(c.y(), 0.5, 1e-15);

  const Loop tri{Point(0, 0), Point(3, 0), Point(0, 6)};
  const Point ct = polygon::centroid(tri, polygon::signed_area(tri));
  EXPECT_NEAR(ct.x(), 1.0, 1e-14);
  EXPECT_NEAR(ct.y(), 2.0, 1e-14);

  // Clockwise loop: same centroid when given its (negative) signed area.
  const Loop cw = reversed(tri);
  const Point ccw = polygon::centroid(cw, polygon::signed_area(cw));
  EXPECT_NEAR(ccw.x(), 1.0, 1e-14);
  EXPECT_NEAR(ccw.y(), 2.0, 1e-14);

  // Arrow: area-weighted centroids of shaft (1.5, 0.5) and head (3 + 1/3, 0.5).
  const Loop a = arrow();
  const Point ca = polygon::centroid(a, polygon::signed_area(a));
  EXPECT_NEAR(ca.x(), (0.6 * 1.5 + 0.5 * (3.0 + 1.0 / 3.0)) / 1.1, 1e-14);
  EXPECT_NEAR(ca.y(), 0.5, 1e-14);
}

TEST(Polygon, CentroidFarFromOrigin) {
  const Loop far = translated(unit_square(), Point(1e7, -3e7));
  const Point c = polygon::centroid(far, polygon::signed_area(far));
  EXPECT_NEAR(c.x(), 1e7 + 0.5, 1e-8);
  EXPECT_NEAR(c.y(), -3e7 + 0.5, 1e-8);
}

TEST(Polygon, SelfIntersectionDetectsBowTie) {
  const Loop bow_tie{Point(0, 0), Point(1, 1), Point(1, 0), Point(0, 1)};
  EXPECT_TRUE(polygon::self_intersects(bow_tie));
  // A bow-tie with positive signed area (edges (1,0)-(0.2,1) and (0.8,1)-(0,0) cross).
  const Loop lopsided{Point(0, 0), Point(1, 0), Point(0.2, 1), Point(0.8, 1)};
  EXPECT_GT(polygon::signed_area(lopsided), 0.0);
  EXPECT_TRUE(polygon::self_intersects(lopsided));
}

TEST(Polygon, SimplePolygonsDoNotSelfIntersect) {
  EXPECT_FALSE(polygon::self_intersects(unit_square()));
  EXPECT_FALSE(polygon::self_intersects(reversed(unit_square())));
  EXPECT_FALSE(polygon::self_intersects(arrow()));
  EXPECT_FALSE(polygon::self_intersects(Loop{Point(0, 0), Point(1, 0), Point(0, 1)}));
  // A regular hexagon.
  Loop hex;
  for (int k = 0; k < 6; ++k)
    hex.emplace_back(std::cos(k * std::numbers::pi / 3), std::sin(k * std::numbers::pi / 3));
  EXPECT_FALSE(polygon::self_intersects(hex));
}

TEST(Polygon, RepeatedVertexOrTouchingEdgesCountAsSelfIntersection) {
  // Vertex 2 repeated later in the loop (a pinched polygon).
  const Loop pinched{Point(0, 0), Point(2, 0), Point(1, 1), Point(2, 2), Point(0, 2), Point(1, 1)};
  EXPECT_TRUE(polygon::self_intersects(pinched));
  // A vertex touching a non-adjacent edge.
  const Loop touching{Point(0, 0), Point(2, 0), Point(2, 2), Point(1, 0), Point(0, 2)};
  EXPECT_TRUE(polygon::self_intersects(touching));
}

TEST(Polygon, ArrowIsStarShapedAboutAKernelPointButNotAboutItsCentroid) {
  const Loop a = arrow();
  const double area = polygon::signed_area(a);
  const Point c = polygon::centroid(a, area);
  const double min_area = 1e-12 * area;
  EXPECT_FALSE(polygon::star_shaped_about(a, c, min_area)) << "centroid " << c.transpose();
  EXPECT_TRUE(polygon::star_shaped_about(a, Point(3.2, 0.5), min_area));
  // Points of the shaft are not in the kernel either.
  EXPECT_FALSE(polygon::star_shaped_about(a, Point(2.9, 0.5), min_area));
}

TEST(Polygon, ConvexPolygonIsStarShapedAboutItsCentroidButNotAboutOutsidePointsOrVertices) {
  const Loop sq = unit_square();
  EXPECT_TRUE(polygon::star_shaped_about(sq, Point(0.5, 0.5), 1e-12));
  EXPECT_FALSE(polygon::star_shaped_about(sq, Point(1.5, 0.5), 1e-12));
  // A point on the boundary makes a zero-area fan triangle.
  EXPECT_FALSE(polygon::star_shaped_about(sq, Point(1.0, 0.5), 1e-12));
  EXPECT_FALSE(polygon::star_shaped_about(sq, Point(0.0, 0.0), 1e-12));
  // Clockwise loops are not star-shaped in the counter-clockwise sense.
  EXPECT_FALSE(polygon::star_shaped_about(reversed(sq), Point(0.5, 0.5), 1e-12));
  // min_area is honoured: a fan triangle of area 0.25 fails a threshold of 0.3.
  EXPECT_FALSE(polygon::star_shaped_about(sq, Point(0.5, 0.5), 0.3));
}

TEST(Polygon, MinInteriorAngle) {
  EXPECT_NEAR(polygon::min_interior_angle(unit_square()), std::numbers::pi / 2, 1e-14);
  const Loop equilateral{Point(0, 0), Point(1, 0), Point(0.5, std::sqrt(3.0) / 2)};
  EXPECT_NEAR(polygon::min_interior_angle(equilateral), std::numbers::pi / 3, 1e-14);
  // Right triangle 3-4-5: smallest angle atan(3/4).
  const Loop right{Point(0, 0), Point(4, 0), Point(0, 3)};
  EXPECT_NEAR(polygon::min_interior_angle(right), std::atan(0.75), 1e-14);
  // Arrow: the head's tip, 2 atan(1/2); reflex corners (270 degrees) do not count as small.
  EXPECT_NEAR(polygon::min_interior_angle(arrow()), 2 * std::atan(0.5), 1e-14);
  // A regular hexagon has 120-degree angles.
  Loop hex;
  for (int k = 0; k < 6; ++k)
    hex.emplace_back(std::cos(k * std::numbers::pi / 3), std::sin(k * std::numbers::pi / 3));
  EXPECT_NEAR(polygon::min_interior_angle(hex), 2 * std::numbers::pi / 3, 1e-14);
}

TEST(Polygon, SegmentsIntersect) {
  using polygon::segments_intersect;
  EXPECT_TRUE(segments_intersect(Point(0, 0), Point(1, 1), Point(0, 1), Point(1, 0)));
  EXPECT_FALSE(segments_intersect(Point(0, 0), Point(1, 0), Point(0, 1), Point(1, 1)));
  // Touching at an end point counts (closed segments).
  EXPECT_TRUE(segments_intersect(Point(0, 0), Point(1, 0), Point(1, 0), Point(2, 5)));
  EXPECT_TRUE(segments_intersect(Point(0, 0), Point(2, 0), Point(1, 0), Point(1, 3)));
  // Collinear: overlapping and disjoint.
  EXPECT_TRUE(segments_intersect(Point(0, 0), Point(2, 0), Point(1, 0), Point(3, 0)));
  EXPECT_FALSE(segments_intersect(Point(0, 0), Point(1, 0), Point(2, 0), Point(3, 0)));
  // Lines cross but segments do not.
  EXPECT_FALSE(segments_intersect(Point(0, 0), Point(1, 1), Point(3, 0), Point(2, 1)));
}

TEST(Polygon, DistanceToSegment) {
  using polygon::distance_to_segment;
  EXPECT_DOUBLE_EQ(distance_to_segment(Point(0.5, 2), Point(0, 0), Point(1, 0)), 2.0);
  EXPECT_DOUBLE_EQ(distance_to_segment(Point(4, 4), Point(0, 0), Point(1, 0)), 5.0);
  EXPECT_DOUBLE_EQ(distance_to_segment(Point(-3, -4), Point(0, 0), Point(1, 0)), 5.0);
  EXPECT_DOUBLE_EQ(distance_to_segment(Point(0.3, 0), Point(0, 0), Point(1, 0)), 0.0);
  // Degenerate segment: distance to the point.
  EXPECT_DOUBLE_EQ(distance_to_segment(Point(3, 4), Point(0, 0), Point(0, 0)), 5.0);
}

}  // namespace
}  // namespace vorodg
