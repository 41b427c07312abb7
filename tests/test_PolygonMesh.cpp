// PolygonMesh on small hand-built meshes: counts, unique edges, edge/cell adjacency, orientation
// of shared edges, boundary side tags, vertex-to-cell map, areas and h_avg, topology defects.
#include "core/mesh/PolygonMesh.hpp"

#include <gtest/gtest.h>

#include <ostream>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "core/util/Errors.hpp"

namespace vorodg {

namespace {

// 2 x 2 unit quads on [0,2]^2; vertex (i, j) has index 3 j + i, cells numbered row by row.
PolygonMesh quads_2x2() {
  std::vector<Point> v;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) v.emplace_back(i, j);
  std::vector<int> offsets{0, 4, 8, 12, 16};
  std::vector<int> cells{0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 7};
  return PolygonMesh(Rectangle(0, 0, 2, 2), v, offsets, cells);
}

// [0,2] x [0,1]: a unit quad on the left, the right square split into two triangles.
//   3---4---5
//   |   | / |
//   0---1---2
PolygonMesh mixed_quad_tri() {
  std::vector<Point> v{Point(0, 0), Point(1, 0), Point(2, 0),
                       Point(0, 1), Point(1, 1), Point(2, 1)};
  std::vector<int> offsets{0, 4, 7, 10};
  std::vector<int> cells{0, 1, 4, 3, 1, 2, 5, 1, 5, 4};
  return PolygonMesh(Rectangle(0, 0, 2, 1), v, offsets, cells);
}

std::pair<int, int> key(int a, int b) {
  return {std::min(a, b), std::max(a, b)};
}

// Checks every structural invariant that holds for a valid mesh.
void expect_consistent(const PolygonMesh& m) {
  // Edges are unique (as unordered pairs).
  std::set<std::pair<int, int>> seen;
  for (const MeshEdge& e : m.edges()) {
    EXPECT_NE(e.v0, e.v1);
    EXPECT_TRUE(seen.insert(key(e.v0, e.v1)).second) << "duplicate edge " << e.v0 << "," << e.v1;
  }
  // cell_edges(c)[k] joins cell_vertices(c)[k] and [k+1]; traversal direction matches cell0/cell1.
  for (int c = 0; c < m.num_cells(); ++c) {
    const auto cv = m.cell_vertices(c);
    const auto ce = m.cell_edges(c);
    ASSERT_EQ(cv.size(), ce.size());
    ASSERT_EQ(static_cast<int>(cv.size()), m.cell_size(c));
    const int n = static_cast<int>(cv.size());
    for (int k = 0; k < n; ++k) {
      const int a = cv[k], b = cv[(k + 1) % n];
      const MeshEdge& e = m.edge(ce[k]);
      EXPECT_EQ(key(e.v0, e.v1), key(a, b));
      if (e.cell0 == c) {
        EXPECT_EQ(e.v0, a) << "cell0 traverses v0 -> v1";
        EXPECT_EQ(e.v1, b);
      } else {
        ASSERT_EQ(e.cell1, c);
        EXPECT_EQ(e.v0, b) << "cell1 traverses v1 -> v0";
        EXPECT_EQ(e.v1, a);
      }
      const int nb = m.neighbor(c, k);
      EXPECT_EQ(nb, e.cell0 == c ? e.cell1 : e.cell0);
    }
  }
  // Each edge is referenced by exactly its cells.
  std::vector<int> uses(m.num_edges(), 0);
  for (int c = 0; c < m.num_cells(); ++c)
    for (int e : m.cell_edges(c)) ++uses[e];
  for (int e = 0; e < m.num_edges(); ++e) {
    EXPECT_EQ(uses[e], m.edge(e).on_boundary() ? 1 : 2) << "edge " << e;
    if (!m.edge(e).on_boundary()) {
      EXPECT_NE(m.edge(e).cell0, m.edge(e).cell1);
    }
  }
  // vertex_cells is the inverse of cell_vertices.
  for (int v = 0; v < m.num_vertices(); ++v) {
    for (int c : m.vertex_cells(v)) {
      const auto cv = m.cell_vertices(c);
      EXPECT_NE(std::find(cv.begin(), cv.end(), v), cv.end());
    }
  }
  for (int c = 0; c < m.num_cells(); ++c)
    for (int v : m.cell_vertices(c)) {
      const auto vc = m.vertex_cells(v);
      EXPECT_NE(std::find(vc.begin(), vc.end(), c), vc.end());
    }
  EXPECT_TRUE(m.topology_defects().empty());
}

std::map<std::pair<int, int>, const MeshEdge*> edge_map(const PolygonMesh& m) {
  std::map<std::pair<int, int>, const MeshEdge*> out;
  for (const MeshEdge& e : m.edges()) out[key(e.v0, e.v1)] = &e;
  return out;
}

TEST(PolygonMesh, QuadGridCounts) {
  const PolygonMesh m = quads_2x2();
  EXPECT_EQ(m.num_vertices(), 9);
  EXPECT_EQ(m.num_cells(), 4);
  EXPECT_EQ(m.num_edges(), 12);
  int boundary = 0;
  for (const MeshEdge& e : m.edges()) boundary += e.on_boundary();
  EXPECT_EQ(boundary, 8);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(m.cell_size(c), 4);
  expect_consistent(m);
}

TEST(PolygonMesh, QuadGridBoundaryEdgesTaggedBySideInteriorEdgesUntagged) {
  const PolygonMesh m = quads_2x2();
  const auto edges = edge_map(m);
  const std::map<std::pair<int, int>, Side> expected{
      {{0, 1}, Side::bottom}, {{1, 2}, Side::bottom}, {{6, 7}, Side::top},   {{7, 8}, Side::top},
      {{0, 3}, Side::left},   {{3, 6}, Side::left},   {{2, 5}, Side::right}, {{5, 8}, Side::right}};
  for (const auto& [k, side] : expected) {
    ASSERT_TRUE(edges.count(k)) << k.first << "," << k.second;
    EXPECT_TRUE(edges.at(k)->on_boundary());
    EXPECT_EQ(edges.at(k)->side, side) << "edge " << k.first << "," << k.second;
    EXPECT_EQ(edges.at(k)->cell1, -1);
  }
  for (const auto& [k, e] : edges) {
    if (expected.count(k)) continue;
    EXPECT_FALSE(e->on_boundary()) << k.first << "," << k.second;
    EXPECT_EQ(e->side, Side::none);
  }
}

TEST(PolygonMesh, QuadGridInteriorEdgesHaveTwoCellsWithOppositeTraversal) {
  const PolygonMesh m = quads_2x2();
  const auto edges = edge_map(m);
  // Edge 1-4 separates cell 0 (traverses 1 -> 4) and cell 1 (traverses 4 -> 1).
  const MeshEdge& e = *edges.at({1, 4});
  EXPECT_EQ(std::set<int>({e.cell0, e.cell1}), std::set<int>({0, 1}));
  if (e.cell0 == 0) {
    EXPECT_EQ(e.v0, 1);
    EXPECT_EQ(e.v1, 4);
  } else {
    EXPECT_EQ(e.v0, 4);
    EXPECT_EQ(e.v1, 1);
  }
  const MeshEdge& f = *edges.at({4, 5});  // cell 1 (5 -> 4) and cell 3 (4 -> 5)
  EXPECT_EQ(std::set<int>({f.cell0, f.cell1}), std::set<int>({1, 3}));
}

TEST(PolygonMesh, QuadGridNeighbors) {
  const PolygonMesh m = quads_2x2();
  // Cell 0 = (0,1,4,3): edges 0-1 (boundary), 1-4 (cell 1), 4-3 (cell 2), 3-0 (boundary).
  EXPECT_EQ(m.neighbor(0, 0), -1);
  EXPECT_EQ(m.neighbor(0, 1), 1);
  EXPECT_EQ(m.neighbor(0, 2), 2);
  EXPECT_EQ(m.neighbor(0, 3), -1);
  // Cell 3 = (4,5,8,7): edges 4-5 (cell 1), 5-8, 8-7 boundary, 7-4 (cell 2).
  EXPECT_EQ(m.neighbor(3, 0), 1);
  EXPECT_EQ(m.neighbor(3, 1), -1);
  EXPECT_EQ(m.neighbor(3, 2), -1);
  EXPECT_EQ(m.neighbor(3, 3), 2);
}

TEST(PolygonMesh, QuadGridVertexCells) {
  const PolygonMesh m = quads_2x2();
  auto cells_of = [&](int v) {
    const auto s = m.vertex_cells(v);
    return std::set<int>(s.begin(), s.end());
  };
  EXPECT_EQ(cells_of(4), std::set<int>({0, 1, 2, 3}));
  EXPECT_EQ(cells_of(0), std::set<int>({0}));
  EXPECT_EQ(cells_of(1), std::set<int>({0, 1}));
  EXPECT_EQ(cells_of(8), std::set<int>({3}));
  EXPECT_EQ(m.vertex_cells(4).size(), 4u);
}

TEST(PolygonMesh, QuadGridAreasCentroidsAndHavg) {
  const PolygonMesh m = quads_2x2();
  for (int c = 0; c < 4; ++c) EXPECT_DOUBLE_EQ(m.cell_area(c), 1.0);
  EXPECT_DOUBLE_EQ(m.total_area(), 4.0);
  EXPECT_DOUBLE_EQ(m.h_avg(), std::sqrt(4.0 / 4.0));
  const Point c3 = m.cell_centroid(3);
  EXPECT_NEAR(c3.x(), 1.5, 1e-15);
  EXPECT_NEAR(c3.y(), 1.5, 1e-15);
  const auto pts = m.cell_points(1);
  ASSERT_EQ(pts.size(), 4u);
  EXPECT_EQ(pts[0], Point(1, 0));
  EXPECT_EQ(pts[2], Point(2, 1));
  EXPECT_DOUBLE_EQ(m.edge_length(0), 1.0);
  EXPECT_EQ(m.offsets(), (std::vector<int>{0, 4, 8, 12, 16}));
  EXPECT_EQ(m.cell_vertex_list().size(), 16u);
  EXPECT_EQ(m.domain().area(), 4.0);
}

TEST(PolygonMesh, MixedQuadTriangleMesh) {
  const PolygonMesh m = mixed_quad_tri();
  EXPECT_EQ(m.num_vertices(), 6);
  EXPECT_EQ(m.num_cells(), 3);
  EXPECT_EQ(m.num_edges(), 8);
  EXPECT_EQ(m.cell_size(0), 4);
  EXPECT_EQ(m.cell_size(1), 3);
  EXPECT_EQ(m.cell_size(2), 3);
  expect_consistent(m);

  const auto edges = edge_map(m);
  EXPECT_EQ(edges.at({0, 1})->side, Side::bottom);
  EXPECT_EQ(edges.at({1, 2})->side, Side::bottom);
  EXPECT_EQ(edges.at({2, 5})->side, Side::right);
  EXPECT_EQ(edges.at({4, 5})->side, Side::top);
  EXPECT_EQ(edges.at({3, 4})->side, Side::top);
  EXPECT_EQ(edges.at({0, 3})->side, Side::left);
  // The diagonal 1-5 is interior even though both ends are on the boundary.
  const MeshEdge& diag = *edges.at({1, 5});
  EXPECT_FALSE(diag.on_boundary());
  EXPECT_EQ(diag.side, Side::none);
  EXPECT_EQ(std::set<int>({diag.cell0, diag.cell1}), std::set<int>({1, 2}));
  const MeshEdge& mid = *edges.at({1, 4});
  EXPECT_EQ(std::set<int>({mid.cell0, mid.cell1}), std::set<int>({0, 2}));

  const auto vc1 = m.vertex_cells(1);
  EXPECT_EQ(std::set<int>(vc1.begin(), vc1.end()), std::set<int>({0, 1, 2}));
  const auto vc4 = m.vertex_cells(4);
  EXPECT_EQ(std::set<int>(vc4.begin(), vc4.end()), std::set<int>({0, 2}));

  EXPECT_DOUBLE_EQ(m.cell_area(0), 1.0);
  EXPECT_DOUBLE_EQ(m.cell_area(1), 0.5);
  EXPECT_DOUBLE_EQ(m.cell_area(2), 0.5);
  EXPECT_DOUBLE_EQ(m.total_area(), 2.0);
  EXPECT_DOUBLE_EQ(m.h_avg(), std::sqrt(2.0 / 3.0));
}

TEST(PolygonMesh, BoundaryTagsUseToleranceRelativeToDomainSize) {
  // A large domain (scale 1e4): a vertex 1e-6 off the bottom side is within 1e-8 * 1e4 = 1e-4.
  const double L = 1e4;
  std::vector<Point> v{Point(0, 1e-6), Point(L, 0), Point(L, L), Point(0, L)};
  const PolygonMesh m(Rectangle(0, 0, L, L), v, {0, 4}, {0, 1, 2, 3});
  const auto edges = edge_map(m);
  EXPECT_EQ(edges.at({0, 1})->side, Side::bottom);
  EXPECT_EQ(edges.at({0, 3})->side, Side::left);
  // A vertex clearly off the side (1e-2 of a unit domain) is not tagged.
  std::vector<Point> w{Point(0, 0.01), Point(1, 0), Point(1, 1), Point(0, 1)};
  const PolygonMesh n(Rectangle(0, 0, 1, 1), w, {0, 4}, {0, 1, 2, 3});
  EXPECT_EQ(edge_map(n).at({0, 1})->side, Side::none);
}

TEST(PolygonMesh, EmptyMeshHasNoCells) {
  const PolygonMesh m;
  EXPECT_EQ(m.num_cells(), 0);
  EXPECT_EQ(m.num_vertices(), 0);
  EXPECT_EQ(m.num_edges(), 0);
  EXPECT_EQ(m.h_avg(), 0.0);
}

TEST(PolygonMesh, ConstructorRejectsIndexErrors) {
  const Rectangle dom(0, 0, 1, 1);
  const std::vector<Point> v{Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)};
  // Vertex out of range.
  EXPECT_THROW(PolygonMesh(dom, v, {0, 4}, {0, 1, 2, 4}), InputError);
  EXPECT_THROW(PolygonMesh(dom, v, {0, 4}, {0, 1, -1, 3}), InputError);
  // Offsets not matching the connectivity.
  EXPECT_THROW(PolygonMesh(dom, v, {0, 5}, {0, 1, 2, 3}), InputError);
  EXPECT_THROW(PolygonMesh(dom, v, {1, 4}, {0, 1, 2, 3}), InputError);
  // Decreasing offsets / cells with fewer than 3 vertices.
  EXPECT_THROW(PolygonMesh(dom, v, {0, 3, 2, 4}, {0, 1, 2, 3}), InputError);
  EXPECT_THROW(PolygonMesh(dom, v, {0, 2, 4}, {0, 1, 2, 3}), InputError);
  EXPECT_THROW(PolygonMesh(dom, v, {}, {}), InputError);
  try {
    PolygonMesh(dom, v, {0, 4}, {0, 1, 2, 7});
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find('7'), std::string::npos) << e.what();
  }
}

TEST(PolygonMesh, RecordsNonManifoldEdge) {
  // Two unit quads sharing edge 1-4 plus a triangle (1,4,6) that also uses edge 1-4.
  std::vector<Point> v{Point(0, 0), Point(1, 0), Point(2, 0),    Point(0, 1),
                       Point(1, 1), Point(2, 1), Point(0.5, 0.5)};
  const PolygonMesh m(Rectangle(0, 0, 2, 1), v, {0, 4, 8, 11}, {0, 1, 4, 3, 1, 2, 5, 4, 6, 1, 4});
  ASSERT_FALSE(m.topology_defects().empty());
  bool found = false;
  for (const TopologyDefect& d : m.topology_defects())
    if (d.kind == TopologyDefect::Kind::non_manifold_edge) {
      found = true;
      EXPECT_EQ(key(d.v0, d.v1), key(1, 4));
      EXPECT_NE(d.what.find('2'), std::string::npos) << d.what;
    }
  EXPECT_TRUE(found);
}

TEST(PolygonMesh, RecordsInconsistentOrientation) {
  // Quad (0,1,4,3) and triangle (0,1,4) both traverse 0 -> 1 and 1 -> 4.
  std::vector<Point> v{Point(0, 0), Point(1, 0), Point(2, 0), Point(0, 1), Point(1, 1)};
  const PolygonMesh m(Rectangle(0, 0, 1, 1), v, {0, 4, 7}, {0, 1, 4, 3, 0, 1, 4});
  int count = 0;
  for (const TopologyDefect& d : m.topology_defects())
    if (d.kind == TopologyDefect::Kind::inconsistent_orientation) ++count;
  EXPECT_GE(count, 2);
}

TEST(PolygonMesh, RecordsConsecutiveRepeatedVertex) {
  std::vector<Point> v{Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)};
  const PolygonMesh m(Rectangle(0, 0, 1, 1), v, {0, 5}, {0, 1, 1, 2, 3});
  ASSERT_EQ(m.topology_defects().size(), 1u);
  EXPECT_EQ(m.topology_defects()[0].kind, TopologyDefect::Kind::degenerate_edge);
}

}  // namespace
}  // namespace vorodg
