// The discontinuous space (interfaces/DgSpace), docs/design.md "Discontinuous Galerkin":
// - DOFs: every cell owns 2 DOFs per vertex copy, cells numbered consecutively
//   (num_dofs = 2 sum_c |c|, cell_dof_count(c) = 2 |c|, offsets contiguous).
// - Interfaces are exactly the interior edges, each once, with cell 1 = edge.cell0 and
//   cell 2 = edge.cell1, end points v0 and v1, and the DOF indices of the two copies of v0 and v1
//   pointing at those vertices in each cell's loop.
// - The normal is the unit outward normal of cell 1: perpendicular to the edge, pointing from
//   cell 1's side (its centroid) towards cell 2's; cell 1 traverses the edge v0 -> v1.
// - length = |b - a| > 0, h_local = (area_1 + area_2) / (2 length) > 0.
// Checked on every test mesh family and on a hand-made two-square mesh with known answers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "core/mesh/PolygonMesh.hpp"
#include "interfaces/DgSpace.hpp"
#include "support/ElementTestMeshes.hpp"

namespace vorodg {
namespace {

using testing::Family;
using testing::kFamilies;
using testing::mesh_of;
using testing::test_name;

int local_index(const PolygonMesh& mesh, int c, int v) {
  const auto loop = mesh.cell_vertices(c);
  const auto it = std::find(loop.begin(), loop.end(), v);
  return it == loop.end() ? -1 : static_cast<int>(it - loop.begin());
}

class DgSpaceFamilies : public ::testing::TestWithParam<Family> {};

TEST_P(DgSpaceFamilies, TwoDofsPerVertexCopy) {
  const PolygonMesh& mesh = mesh_of(GetParam());
  const DgSpace space(mesh);
  EXPECT_EQ(&space.mesh(), &mesh);
  int copies = 0;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    EXPECT_EQ(space.cell_dof_count(c), 2 * mesh.cell_size(c)) << "cell " << c;
    EXPECT_EQ(space.dof(c, 0), 2 * copies) << "cell " << c;
    copies += mesh.cell_size(c);
  }
  EXPECT_EQ(space.num_dofs(), 2 * copies);
  EXPECT_EQ(space.num_dofs(), 2 * static_cast<int>(mesh.cell_vertex_list().size()));
  EXPECT_GT(space.num_dofs(), 2 * mesh.num_vertices());  // copies: more DOFs than CG
  EXPECT_EQ(space.dof(0, 0), 0);
  const int last = mesh.num_cells() - 1;
  EXPECT_EQ(space.dof(last, 0) + space.cell_dof_count(last), space.num_dofs());
}

TEST_P(DgSpaceFamilies, InterfacesAreTheInteriorEdges) {
  const PolygonMesh& mesh = mesh_of(GetParam());
  const DgSpace space(mesh);
  int interior = 0;
  for (const MeshEdge& e : mesh.edges()) interior += !e.on_boundary();
  ASSERT_EQ(static_cast<int>(space.interfaces().size()), interior);
  std::map<int, int> seen;
  for (const Interface& f : space.interfaces()) {
    ASSERT_GE(f.edge, 0);
    ASSERT_LT(f.edge, mesh.num_edges());
    ++seen[f.edge];
    const MeshEdge& e = mesh.edge(f.edge);
    EXPECT_FALSE(e.on_boundary()) << "edge " << f.edge;
    EXPECT_EQ(f.cell[0], e.cell0) << "edge " << f.edge;
    EXPECT_EQ(f.cell[1], e.cell1) << "edge " << f.edge;
    EXPECT_NE(f.cell[0], f.cell[1]);
    EXPECT_EQ(f.a, mesh.vertex(e.v0)) << "edge " << f.edge;
    EXPECT_EQ(f.b, mesh.vertex(e.v1)) << "edge " << f.edge;
  }
  EXPECT_EQ(static_cast<int>(seen.size()), interior) << "an interior edge appears twice";
}

TEST_P(DgSpaceFamilies, InterfaceDofsAreTheEndVerticesCopies) {
  const PolygonMesh& mesh = mesh_of(GetParam());
  const DgSpace space(mesh);
  for (const Interface& f : space.interfaces()) {
    const MeshEdge& e = mesh.edge(f.edge);
    for (int s = 0; s < 2; ++s) {
      const int c = f.cell[s], first = space.dof(c, 0);
      for (const auto& [dof, v] : {std::pair{f.dof_v0[s], e.v0}, std::pair{f.dof_v1[s], e.v1}}) {
        ASSERT_GE(dof, first) << "edge " << f.edge << " side " << s;
        ASSERT_LT(dof + 1, first + space.cell_dof_count(c)) << "edge " << f.edge << " side " << s;
        EXPECT_EQ((dof - first) % 2, 0) << "edge " << f.edge << " side " << s;
        EXPECT_EQ((dof - first) / 2, local_index(mesh, c, v)) << "edge " << f.edge << " side " << s;
      }
    }
  }
}

TEST_P(DgSpaceFamilies, NormalIsOutwardFromCellOne) {
  const PolygonMesh& mesh = mesh_of(GetParam());
  const DgSpace space(mesh);
  for (const Interface& f : space.interfaces()) {
    const Eigen::Vector2d t = f.b - f.a, mid = 0.5 * (f.a + f.b);
    const Point c1 = mesh.cell_centroid(f.cell[0]), c2 = mesh.cell_centroid(f.cell[1]);
    EXPECT_NEAR(f.normal.norm(), 1.0, 1e-14) << "edge " << f.edge;
    EXPECT_NEAR(f.normal.dot(t), 0.0, 1e-14 * t.norm()) << "edge " << f.edge;
    EXPECT_GT(f.normal.dot(mid - c1), 0.0) << "edge " << f.edge << ": n points into cell 1";
    EXPECT_LT(f.normal.dot(mid - c2), 0.0) << "edge " << f.edge << ": n points out of cell 2";
    EXPECT_GT(f.normal.dot(c2 - c1), 0.0)
        << "edge " << f.edge << ": n does not point towards cell 2";
    // Cell 1 runs the edge v0 -> v1 counter-clockwise (so (t_y, -t_x) is its outward normal).
    const auto loop = mesh.cell_vertices(f.cell[0]);
    const int n = static_cast<int>(loop.size());
    const int k0 = local_index(mesh, f.cell[0], mesh.edge(f.edge).v0);
    EXPECT_EQ(loop[(k0 + 1) % n], mesh.edge(f.edge).v1) << "edge " << f.edge;
  }
}

TEST_P(DgSpaceFamilies, LengthAndLocalSize) {
  const PolygonMesh& mesh = mesh_of(GetParam());
  const DgSpace space(mesh);
  for (const Interface& f : space.interfaces()) {
    EXPECT_GT(f.length, 0.0) << "edge " << f.edge;
    EXPECT_NEAR(f.length, (f.b - f.a).norm(), 1e-15) << "edge " << f.edge;
    EXPECT_NEAR(f.length, mesh.edge_length(f.edge), 1e-15) << "edge " << f.edge;
    const double h = (mesh.cell_area(f.cell[0]) + mesh.cell_area(f.cell[1])) / (2.0 * f.length);
    EXPECT_GT(f.h_local, 0.0) << "edge " << f.edge;
    EXPECT_NEAR(f.h_local, h, 1e-13 * h) << "edge " << f.edge;
  }
}

INSTANTIATE_TEST_SUITE_P(Families, DgSpaceFamilies, ::testing::ValuesIn(kFamilies),
                         [](const auto& info) { return test_name(info.param.name); });

// Two unit squares side by side on [0,2] x [0,1]: one interface on x = 1.
TEST(DgSpace, TwoSquares) {
  //  3 --- 4 --- 5
  //  |  0  |  1  |
  //  0 --- 1 --- 2
  const std::vector<Point> p = {{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}};
  const PolygonMesh mesh(Rectangle(0, 0, 2, 1), p, {0, 4, 8}, {0, 1, 4, 3, 1, 2, 5, 4});
  const DgSpace space(mesh);
  EXPECT_EQ(space.num_dofs(), 16);
  EXPECT_EQ(space.dof(0, 0), 0);
  EXPECT_EQ(space.dof(1, 0), 8);
  EXPECT_EQ(space.cell_dof_count(0), 8);
  EXPECT_EQ(space.cell_dof_count(1), 8);
  ASSERT_EQ(space.interfaces().size(), 1u);
  const Interface& f = space.interfaces()[0];
  EXPECT_DOUBLE_EQ(f.length, 1.0);
  EXPECT_DOUBLE_EQ(f.h_local, 1.0);  // (1 + 1) / (2 * 1)
  // Whichever cell is cell 1, the normal points from it to the other one.
  const Eigen::Vector2d expected = f.cell[0] == 0 ? Eigen::Vector2d(1, 0) : Eigen::Vector2d(-1, 0);
  EXPECT_NEAR((f.normal - expected).norm(), 0.0, 1e-15) << f.normal.transpose();
  EXPECT_EQ(std::min(f.cell[0], f.cell[1]), 0);
  EXPECT_EQ(std::max(f.cell[0], f.cell[1]), 1);
  // Vertex 1 is local 1 in cell 0 and local 0 in cell 1; vertex 4 local 2 in cell 0, 3 in cell 1.
  const int dof_of[2][6] = {{-1, 2, -1, -1, 4, -1}, {-1, 8, -1, -1, 14, -1}};
  const MeshEdge& e = mesh.edge(f.edge);
  for (int s = 0; s < 2; ++s) {
    EXPECT_EQ(f.dof_v0[s], dof_of[f.cell[s]][e.v0]) << "side " << s;
    EXPECT_EQ(f.dof_v1[s], dof_of[f.cell[s]][e.v1]) << "side " << s;
  }
}

// A 3 x 2 grid of squares with unequal widths: 7 interfaces; h_local from the two areas.
TEST(DgSpace, UnequalCellsLocalSize) {
  const std::vector<double> xs = {0.0, 0.5, 1.5, 2.0}, ys = {0.0, 0.25, 1.0};
  std::vector<Point> p;
  for (double y : ys)
    for (double x : xs) p.emplace_back(x, y);
  std::vector<int> offsets{0}, cells;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      const int v = 4 * j + i;
      cells.insert(cells.end(), {v, v + 1, v + 5, v + 4});
      offsets.push_back(static_cast<int>(cells.size()));
    }
  const PolygonMesh mesh(Rectangle(0, 0, 2, 1), p, offsets, cells);
  const DgSpace space(mesh);
  EXPECT_EQ(space.num_dofs(), 48);
  ASSERT_EQ(space.interfaces().size(), 7u);  // 4 vertical + 3 horizontal interior edges
  for (const Interface& f : space.interfaces()) {
    const double expected =
        (mesh.cell_area(f.cell[0]) + mesh.cell_area(f.cell[1])) / (2.0 * mesh.edge_length(f.edge));
    EXPECT_NEAR(f.h_local, expected, 1e-15);
    const Eigen::Vector2d d = mesh.cell_centroid(f.cell[1]) - mesh.cell_centroid(f.cell[0]);
    // Axis-aligned: the normal is the unit vector along the centroid offset's dominant axis.
    const Eigen::Vector2d axis = std::abs(d.x()) > std::abs(d.y())
                                     ? Eigen::Vector2d(d.x() > 0 ? 1 : -1, 0)
                                     : Eigen::Vector2d(0, d.y() > 0 ? 1 : -1);
    EXPECT_NEAR((f.normal - axis).norm(), 0.0, 1e-15);
  }
  // The middle-bottom / middle-top pair: areas 0.25 and 0.75 over length 1.
  for (const Interface& f : space.interfaces())
    if (std::min(f.cell[0], f.cell[1]) == 1 && std::max(f.cell[0], f.cell[1]) == 4) {
      EXPECT_NEAR(f.h_local, 0.5, 1e-15);
    }
}

}  // namespace
}  // namespace vorodg
