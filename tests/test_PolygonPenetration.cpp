// Vertex-in-polygon penetration: depth, normal and reaction point on squares with known answers,
// a reflex vertex of a non-convex polygon, exits restricted to exposed edges, and on random
// overlapping rcp cells the geometric facts the penalty law relies on (q - p = d n, d the
// distance to the boundary, inside agreeing with the convex-polygon test).
#include "dynamics/contact/PolygonPenetration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/geometry/Polygon.hpp"
#include "support/ContactScenes.hpp"

namespace vorodg {
namespace {

using Loop = std::vector<Point>;

const Loop kSquare{Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)};

Point reaction_point(const Loop& b, const Penetration& pen) {
  const Point& a = b[pen.edge];
  return a + pen.t * (b[(pen.edge + 1) % b.size()] - a);
}

TEST(PolygonPenetration, PointInSquareLeavesThroughTheNearestEdge) {
  const auto pen = PolygonPenetration::of_point(Point(0.5, 0.1), kSquare, {});
  ASSERT_TRUE(pen);
  EXPECT_EQ(pen->edge, 0);
  EXPECT_NEAR(pen->t, 0.5, 1e-15);
  EXPECT_NEAR(pen->depth, 0.1, 1e-15);
  EXPECT_NEAR((pen->normal - Point(0, -1)).norm(), 0.0, 1e-15);
}

TEST(PolygonPenetration, CornerOfOneSquareInAnother) {
  const Loop a{Point(0.9, 0.95), Point(1.9, 0.95), Point(1.9, 1.95), Point(0.9, 1.95)};
  std::vector<Penetration> found;
  PolygonPenetration::vertices_inside(a, kSquare, {}, found);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].vertex, 0);
  EXPECT_EQ(found[0].edge, 2);  // the top edge, 0.05 away (the right edge is 0.1 away)
  EXPECT_NEAR(found[0].t, 0.1, 1e-14);
  EXPECT_NEAR(found[0].depth, 0.05, 1e-14);
  EXPECT_NEAR((found[0].normal - Point(0, 1)).norm(), 0.0, 1e-14);
  found.clear();
  PolygonPenetration::vertices_inside(kSquare, a, {}, found);  // the other pass: B's corner
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].vertex, 2);
  EXPECT_NEAR(found[0].depth, 0.05, 1e-14);
  EXPECT_NEAR((found[0].normal - Point(0, -1)).norm(), 0.0, 1e-14);
}

TEST(PolygonPenetration, OutsideAndOnTheBoundaryGiveNothing) {
  for (const Point& p :
       {Point(1.5, 0.5), Point(-1e-9, 0.5), Point(0.5, 0.0), Point(1.0, 1.0), Point(0.0, 0.3)})
    EXPECT_FALSE(PolygonPenetration::of_point(p, kSquare, {})) << p.transpose();
}

TEST(PolygonPenetration, ReflexVertexOfANonConvexPolygonIsTheClosestPoint) {
  // An L: the reflex corner (1, 1) is the closest boundary point of p = (0.9, 0.9).
  const Loop l{Point(0, 0), Point(2, 0), Point(2, 1), Point(1, 1), Point(1, 2), Point(0, 2)};
  const auto pen = PolygonPenetration::of_point(Point(0.9, 0.9), l, {});
  ASSERT_TRUE(pen);
  EXPECT_NEAR((reaction_point(l, *pen) - Point(1, 1)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(pen->depth, std::sqrt(0.02), 1e-15);
  EXPECT_NEAR((pen->normal - Point(1, 1).normalized()).norm(), 0.0, 1e-15);
  // The notch of the L is outside.
  EXPECT_FALSE(PolygonPenetration::of_point(Point(1.5, 1.5), l, {}));
}

TEST(PolygonPenetration, ExitsRestrictTheEdges) {
  const std::vector<char> top_only{0, 0, 1, 0};
  const auto pen = PolygonPenetration::of_point(Point(0.5, 0.1), kSquare, top_only);
  ASSERT_TRUE(pen);
  EXPECT_EQ(pen->edge, 2);
  EXPECT_NEAR(pen->depth, 0.9, 1e-15);
  EXPECT_NEAR((pen->normal - Point(0, 1)).norm(), 0.0, 1e-15);
}

TEST(PolygonPenetration, RandomOverlapsOfRcpCellsAreConsistent) {
  const auto scene = testing::two_bodies(0.1, 9, Point(0.7, 0.5), 0.7, 0.3);
  const PolygonMesh& mesh = scene.mesh;
  auto loop = [&](int c) {
    return std::span<const Point>(scene.x).subspan(mesh.offsets()[c], mesh.cell_size(c));
  };
  int found = 0;
  for (int a = 0; a < scene.first_body_cells; ++a)
    for (int b = scene.first_body_cells; b < mesh.num_cells(); ++b)
      for (const Point& p : loop(a)) {
        const auto lb = loop(b);
        // Jiggled rcp cells stay convex here; compare with the convex test away from edges.
        double nearest = std::numeric_limits<double>::infinity();
        bool left_of_all = true;
        for (std::size_t k = 0; k < lb.size(); ++k) {
          const Point& e0 = lb[k];
          const Point& e1 = lb[(k + 1) % lb.size()];
          nearest = std::min(nearest, polygon::distance_to_segment(p, e0, e1));
          left_of_all = left_of_all && polygon::orient2(e0, e1, p) > 0.0;
        }
        if (nearest < 1e-12) continue;
        const auto pen = PolygonPenetration::of_point(p, lb, {});
        const bool convex = polygon::min_interior_angle(lb) > 0 &&
                            polygon::max_interior_angle(lb) < std::numbers::pi;
        if (convex) {
          EXPECT_EQ(bool(pen), left_of_all);
        }
        if (!pen) continue;
        ++found;
        const Loop bl(lb.begin(), lb.end());
        EXPECT_NEAR(pen->depth, nearest, 1e-14);
        EXPECT_NEAR(pen->normal.norm(), 1.0, 1e-14);
        EXPECT_NEAR((reaction_point(bl, *pen) - p - pen->depth * pen->normal).norm(), 0.0, 1e-14);
        EXPECT_GE(pen->t, 0.0);
        EXPECT_LE(pen->t, 1.0);
      }
  EXPECT_GT(found, 100);
}

}  // namespace
}  // namespace vorodg
