// compute_statistics and side_count_histogram on small meshes with known answers.
#include "core/mesh/MeshStatistics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <vector>

namespace vorodg {
namespace {

TEST(MeshStatistics, QuadGrid) {
  std::vector<Point> v;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) v.emplace_back(0.5 * i, 0.5 * j);
  const PolygonMesh m(Rectangle(0, 0, 1, 1), v, {0, 4, 8, 12, 16},
                      {0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 7});
  const MeshStatistics s = compute_statistics(m);
  EXPECT_EQ(s.cells, 4);
  EXPECT_EQ(s.vertices, 9);
  EXPECT_EQ(s.edges, 12);
  EXPECT_EQ(s.boundary_edges, 8);
  EXPECT_DOUBLE_EQ(s.h_avg, 0.5);
  EXPECT_DOUBLE_EQ(s.min_edge, 0.5);
  EXPECT_DOUBLE_EQ(s.max_edge, 0.5);
  EXPECT_DOUBLE_EQ(s.min_edge_over_h, 1.0);
  EXPECT_NEAR(s.min_interior_angle_deg, 90.0, 1e-12);
  EXPECT_NEAR(s.max_interior_angle_deg, 90.0, 1e-12);
  EXPECT_LT(s.area_error, 1e-15);
  EXPECT_EQ(s.side_counts, (std::map<int, int>{{4, 4}}));
  EXPECT_EQ(s.most_common_sides, 4);
  EXPECT_EQ(side_count_histogram(m), s.side_counts);
}

TEST(MeshStatistics, MixedMeshWithHangingVertex) {
  // Quad (0,0)-(1,0)-(1,1)-(0,1) with a hanging vertex at (1,0.5), and two triangles to its right.
  const std::vector<Point> v{Point(0, 0), Point(1, 0), Point(2, 0),  Point(0, 1),
                             Point(1, 1), Point(2, 1), Point(1, 0.5)};
  const PolygonMesh m(Rectangle(0, 0, 2, 1), v, {0, 5, 8, 11, 14},
                      {0, 1, 6, 4, 3, 1, 2, 6, 2, 5, 6, 6, 5, 4});
  const MeshStatistics s = compute_statistics(m);
  EXPECT_EQ(s.cells, 4);
  EXPECT_EQ(s.vertices, 7);
  EXPECT_EQ(s.boundary_edges, 6);
  EXPECT_EQ(s.edges, 10);
  EXPECT_DOUBLE_EQ(s.h_avg, std::sqrt(2.0 / 4.0));
  EXPECT_DOUBLE_EQ(s.min_edge, 0.5);
  EXPECT_DOUBLE_EQ(s.max_edge, std::sqrt(1.25));
  EXPECT_DOUBLE_EQ(s.min_edge_over_h, 0.5 / std::sqrt(0.5));
  // Smallest angle: at (2,0) between the bottom side and the edge to (1,0.5): atan(1/2).
  EXPECT_NEAR(s.min_interior_angle_deg, std::atan(0.5) * 180 / std::numbers::pi, 1e-10);
  EXPECT_NEAR(s.max_interior_angle_deg, 180.0, 1e-10);  // the hanging vertex
  EXPECT_LT(s.area_error, 1e-15);
  EXPECT_EQ(s.side_counts, (std::map<int, int>{{3, 3}, {5, 1}}));
  EXPECT_EQ(s.most_common_sides, 3);
}

TEST(MeshStatistics, AreaErrorOfAnIncompleteMesh) {
  // One unit square on a 2 x 1 domain: half the area is missing.
  const std::vector<Point> v{Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)};
  const PolygonMesh m(Rectangle(0, 0, 2, 1), v, {0, 4}, {0, 1, 2, 3});
  EXPECT_NEAR(compute_statistics(m).area_error, 0.5, 1e-15);
}

}  // namespace
}  // namespace vorodg
