// The cells' small-strain rotation (CorotationalFrames::mean_rotation), on every mesh family,
// continuous and fully split DOF maps:
//   - a rigid rotation u = theta (-y, x) about any point gives theta in every cell, to 1e-12;
//   - a symmetric gradient (pure strain, u = E x with E symmetric) gives 0, to 1e-12 of |E|;
//   - a general affine field gives its gradient's skew part (du_y/dx - du_x/dy) / 2;
//   - a fully split map, each cell rotated by its own angle, gives each cell its own angle.
#include <gtest/gtest.h>

#include <cmath>

#include "core/dofs/SplitDofMap.hpp"
#include "dynamics/CorotationalFrames.hpp"
#include "support/ElementTestMeshes.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;

/// Node displacements of the affine field u(X) = G (X - X0), node by node.
Eigen::VectorXd affine(const PolygonMesh& mesh, const SplitDofMap& dofs, const Eigen::Matrix2d& g,
                       const Point& origin) {
  Eigen::VectorXd u(2 * dofs.num_nodes());
  for (int c = 0; c < mesh.num_cells(); ++c)
    for (int k = 0; k < mesh.cell_size(c); ++k)
      u.segment<2>(2 * dofs.node(c, k)) = g * (mesh.vertex(mesh.cell_vertices(c)[k]) - origin);
  return u;
}

class CellRotation : public ::testing::TestWithParam<Family> {};

TEST_P(CellRotation, AffineFieldsGiveTheirSkewPart) {
  const PolygonMesh& mesh = mesh_of(GetParam());
  const SplitDofMap dofs = SplitDofMap::continuous(mesh);
  const CorotationalFrames frames(mesh);
  const Point origin(0.7, -0.3);
  const double theta = 0.37;
  Eigen::Matrix2d spin, strain, general;
  spin << 0, -theta, theta, 0;
  strain << 2e-3, 5e-4, 5e-4, -1e-3;
  general << 0.2, -0.5, 0.3, 0.1;  // skew part (0.3 - (-0.5)) / 2 = 0.4
  for (int c = 0; c < mesh.num_cells(); ++c) {
    EXPECT_NEAR(frames.mean_rotation(c, dofs, affine(mesh, dofs, spin, origin)), theta, 1e-12);
    EXPECT_NEAR(frames.mean_rotation(c, dofs, affine(mesh, dofs, strain, origin)), 0.0,
                1e-12 * 2e-3);
    EXPECT_NEAR(frames.mean_rotation(c, dofs, affine(mesh, dofs, general, origin)), 0.4, 1e-12);
  }
  EXPECT_NEAR(frames.largest_mean_rotation(dofs, affine(mesh, dofs, spin, origin)), theta, 1e-12);
}

TEST_P(CellRotation, SplitCellsRotateOnTheirOwn) {
  const PolygonMesh& mesh = mesh_of(GetParam());
  const SplitDofMap dofs = SplitDofMap::discontinuous(mesh);
  const CorotationalFrames frames(mesh);
  Eigen::VectorXd u(2 * dofs.num_nodes());
  auto angle = [](int c) { return 0.01 * (c % 7) - 0.03; };
  for (int c = 0; c < mesh.num_cells(); ++c)
    for (int k = 0; k < mesh.cell_size(c); ++k) {
      const Point x = mesh.vertex(mesh.cell_vertices(c)[k]);
      u.segment<2>(2 * dofs.node(c, k)) = angle(c) * Point(-x.y(), x.x());
    }
  for (int c = 0; c < mesh.num_cells(); ++c)
    EXPECT_NEAR(frames.mean_rotation(c, dofs, u), angle(c), 1e-12);
  EXPECT_NEAR(frames.largest_mean_rotation(dofs, u), 0.03, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Families, CellRotation, ::testing::ValuesIn(kFamilies),
                         [](const auto& info) { return test_name(info.param.name); });

}  // namespace
}  // namespace vorodg
