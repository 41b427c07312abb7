// The set of contact cells: it starts as the cells with a boundary edge, grows by add and expose,
// never shrinks, keeps its order of entry, and calls two cells neighbours exactly when they share
// a mesh vertex and no released edge lies between them.
#include "dynamics/contact/SurfaceCells.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Random.hpp"

namespace vorodg {
namespace {

PolygonMesh rcp(std::uint64_t seed) {
  MeshSpec spec;
  spec.domain = Rectangle(0.0, 0.0, 2.0, 1.0);
  spec.size = 0.1;
  spec.seed = seed;
  return generate_mesh(spec).mesh;
}

TEST(SurfaceCells, StartsAsTheCellsWithABoundaryEdge) {
  const PolygonMesh mesh = rcp(1);
  const SurfaceCells surface(mesh);
  std::vector<int> expected;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    bool boundary = false;
    const auto edges = mesh.cell_edges(c);
    for (std::size_t k = 0; k < edges.size(); ++k) {
      const bool b = mesh.edge(edges[k]).on_boundary();
      EXPECT_EQ(surface.exposed(c, int(k)), b);
      boundary = boundary || b;
    }
    if (boundary) expected.push_back(c);
    EXPECT_EQ(surface.contains(c), boundary);
  }
  EXPECT_EQ(std::vector<int>(surface.cells().begin(), surface.cells().end()), expected);
  EXPECT_GT(surface.size(), 0);
  EXPECT_LT(surface.size(), mesh.num_cells());
}

TEST(SurfaceCells, GrowsMonotonicallyAndAddIsIdempotent) {
  const PolygonMesh mesh = rcp(2);
  SurfaceCells surface(mesh);
  Random random(3);
  std::vector<int> before(surface.cells().begin(), surface.cells().end());
  for (int step = 0; step < 3 * mesh.num_cells(); ++step) {
    const int c = static_cast<int>(random.index(mesh.num_cells()));
    const bool was_in = surface.contains(c);
    EXPECT_EQ(surface.add(c), !was_in);
    EXPECT_FALSE(surface.add(c));  // a second add changes nothing
    if (step % 7 == 0) surface.expose(static_cast<int>(random.index(mesh.num_edges())));
    // Monotone: every earlier member is still there, at its old place.
    ASSERT_GE(surface.size(), int(before.size()));
    EXPECT_TRUE(std::equal(before.begin(), before.end(), surface.cells().begin()));
    EXPECT_TRUE(surface.contains(c));
    before.assign(surface.cells().begin(), surface.cells().end());
  }
  for (int c = 0; c < mesh.num_cells(); ++c) surface.add(c);
  EXPECT_EQ(surface.size(), mesh.num_cells());  // every cell once, however often it was added
}

TEST(SurfaceCells, ExposeMarksTheEdgeInBothCellsAndAddsThem) {
  const PolygonMesh mesh = rcp(4);
  SurfaceCells surface(mesh);
  int e = 0;
  while (mesh.edge(e).on_boundary() || surface.contains(mesh.edge(e).cell0) ||
         surface.contains(mesh.edge(e).cell1))
    ++e;  // an interior edge between two interior cells
  const MeshEdge& edge = mesh.edge(e);
  EXPECT_FALSE(surface.has_exposed_edge(edge.cell0));
  surface.expose(e);
  surface.expose(e);  // idempotent
  for (int c : {edge.cell0, edge.cell1}) {
    EXPECT_TRUE(surface.contains(c));
    const auto edges = mesh.cell_edges(c);
    for (std::size_t k = 0; k < edges.size(); ++k)
      EXPECT_EQ(surface.exposed(c, int(k)), edges[k] == e);
  }
  EXPECT_EQ(std::count(surface.cells().begin(), surface.cells().end(), edge.cell0), 1);
}

TEST(SurfaceCells, NeighboursAreCellsThatShareAVertex) {
  const PolygonMesh mesh = rcp(5);
  const SurfaceCells surface(mesh);
  Random random(6);
  int shared = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const int a = static_cast<int>(random.index(mesh.num_cells()));
    // Half the draws from a's vertex patch, so that both answers occur often.
    int b = static_cast<int>(random.index(mesh.num_cells()));
    if (trial % 2) {
      const auto loop = mesh.cell_vertices(a);
      const auto cells = mesh.vertex_cells(loop[random.index(loop.size())]);
      b = cells[random.index(cells.size())];
    }
    bool expected = false;
    for (int v : mesh.cell_vertices(a))
      for (int w : mesh.cell_vertices(b)) expected = expected || v == w;
    EXPECT_EQ(surface.neighbours(a, b), expected) << a << ", " << b;
    EXPECT_EQ(surface.neighbours(b, a), expected);
    shared += expected;
  }
  EXPECT_GT(shared, 5000);
}

TEST(SurfaceCells, ReleasedEdgePartsItsTwoCellsAlone) {
  const PolygonMesh mesh = rcp(8);
  SurfaceCells surface(mesh);
  int e = 0;
  while (mesh.edge(e).on_boundary()) ++e;
  const MeshEdge& edge = mesh.edge(e);
  EXPECT_THROW(surface.release(e), InputError);  // not exposed yet
  surface.expose(e);
  ASSERT_TRUE(surface.neighbours(edge.cell0, edge.cell1));
  surface.release(e);
  surface.release(e);  // idempotent
  EXPECT_FALSE(surface.neighbours(edge.cell0, edge.cell1));
  EXPECT_FALSE(surface.neighbours(edge.cell1, edge.cell0));
  // Every other pair keeps its answer: sharing a vertex makes neighbours.
  for (int a : {edge.cell0, edge.cell1})
    for (int v : mesh.cell_vertices(a))
      for (int b : mesh.vertex_cells(v)) {
        if ((a == edge.cell0 && b == edge.cell1) || (a == edge.cell1 && b == edge.cell0)) continue;
        EXPECT_TRUE(surface.neighbours(a, b)) << a << ", " << b;
      }
  int boundary = 0;
  while (!mesh.edge(boundary).on_boundary()) ++boundary;
  EXPECT_THROW(surface.release(boundary), InputError);
  EXPECT_THROW(surface.release(mesh.num_edges()), InputError);
}

TEST(SurfaceCells, RefusesIndicesOutOfRange) {
  const PolygonMesh mesh = rcp(7);
  SurfaceCells surface(mesh);
  EXPECT_THROW(surface.add(-1), InputError);
  EXPECT_THROW(surface.add(mesh.num_cells()), InputError);
  EXPECT_THROW(surface.expose(mesh.num_edges()), InputError);
}

}  // namespace
}  // namespace vorodg
