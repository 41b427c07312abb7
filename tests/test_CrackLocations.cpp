// Where a body broke (verification/kinds/dynamics/CrackLocations), on a quad mesh of the report's
// column (0.3 x 1.83 m, struck at its bottom-left corner): every edge is placed by its midpoint,
// within one width (0.3 m) of the corner, in the middle third of the height, or elsewhere; the
// fractions add to one; no broken edge gives NaN.
#include "dynamics/problems/CrackLocations.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/meshgen/MeshFamily.hpp"

namespace vorodg {
namespace {

TEST(CrackLocations, EdgesArePlacedByTheirMidpoints) {
  MeshSpec spec;
  spec.family = MeshFamily::quad;
  spec.domain = Rectangle(0, 0, 0.3, 1.83);
  spec.size = 0.05;
  const PolygonMesh mesh = generate_mesh(spec).mesh;
  std::vector<int> all, near, middle, other;
  for (int e = 0; e < mesh.num_edges(); ++e) {
    all.push_back(e);
    const Point mid = 0.5 * (mesh.vertex(mesh.edge(e).v0) + mesh.vertex(mesh.edge(e).v1));
    if (mid.norm() < 0.3)
      near.push_back(e);
    else if (mid.y() > 1.83 / 3 && mid.y() < 2 * 1.83 / 3)
      middle.push_back(e);
    else
      other.push_back(e);
  }
  ASSERT_FALSE(near.empty());
  ASSERT_FALSE(middle.empty());
  const Point corner(0, 0);
  const CrackLocations at_corner = crack_locations(mesh, near, spec.domain, corner);
  EXPECT_EQ(at_corner.near_impact, 1.0);
  EXPECT_EQ(crack_locations(mesh, middle, spec.domain, corner).mid_length, 1.0);
  EXPECT_EQ(crack_locations(mesh, other, spec.domain, corner).elsewhere, 1.0);
  const CrackLocations every = crack_locations(mesh, all, spec.domain, corner);
  const double n = static_cast<double>(all.size());
  EXPECT_DOUBLE_EQ(every.near_impact, near.size() / n);
  EXPECT_DOUBLE_EQ(every.mid_length, middle.size() / n);
  EXPECT_NEAR(every.near_impact + every.mid_length + every.elsewhere, 1.0, 1e-15);
  EXPECT_TRUE(std::isnan(crack_locations(mesh, {}, spec.domain, corner).near_impact));
}

}  // namespace
}  // namespace vorodg
