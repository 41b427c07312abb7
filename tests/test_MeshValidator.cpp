// validate_mesh: valid meshes pass; each defect kind is reported on a small hand-built mesh, with
// the index of the cell / vertex / edge it is about named in its one-line message.
#include "core/mesh/MeshValidator.hpp"

#include <gtest/gtest.h>

#include <ostream>

#include <algorithm>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace vorodg {

namespace {

using Kind = MeshDefect::Kind;

struct MeshInput {
  Rectangle domain;
  std::vector<Point> vertices;
  std::vector<int> offsets;
  std::vector<int> cells;
  PolygonMesh build() const { return PolygonMesh(domain, vertices, offsets, cells); }
};

// n x m unit quads on [0,n] x [0,m]; vertex (i, j) has index (n+1) j + i, cells row by row.
MeshInput quad_grid(int n, int m) {
  MeshInput in{Rectangle(0, 0, n, m), {}, {0}, {}};
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= n; ++i) in.vertices.emplace_back(i, j);
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = (n + 1) * j + i;
      for (int v : {a, a + 1, a + n + 2, a + n + 1}) in.cells.push_back(v);
      in.offsets.push_back(static_cast<int>(in.cells.size()));
    }
  return in;
}

void append_cell(MeshInput& in, std::vector<int> cell) {
  in.cells.insert(in.cells.end(), cell.begin(), cell.end());
  in.offsets.push_back(static_cast<int>(in.cells.size()));
}

// Replaces cell c's loop.
void set_cell(MeshInput& in, int c, const std::vector<int>& cell) {
  const int n = in.offsets[c + 1] - in.offsets[c];
  ASSERT_EQ(static_cast<int>(cell.size()), n);
  std::copy(cell.begin(), cell.end(), in.cells.begin() + in.offsets[c]);
}

// Domain [0,4] x [0,1] tiled by five cells, cell 2 an arrow pointing right: a thin shaft from the
// left side and a triangular head. The arrow is a simple counter-clockwise polygon whose centroid
// (x ~ 2.33, in the shaft) lies outside its kernel (x >= 3): the centroid fan is inverted.
MeshInput arrow_tiling() {
  MeshInput in{Rectangle(0, 0, 4, 1),
               {Point(0, 0), Point(3, 0), Point(4, 0), Point(0, 0.4), Point(3, 0.4), Point(4, 0.5),
                Point(0, 0.6), Point(3, 0.6), Point(0, 1), Point(3, 1), Point(4, 1)},
               {0},
               {}};
  append_cell(in, {0, 1, 4, 3});           // bottom-left rectangle
  append_cell(in, {1, 2, 5});              // bottom-right triangle
  append_cell(in, {3, 4, 1, 5, 9, 7, 6});  // the arrow
  append_cell(in, {6, 7, 9, 8});           // top-left rectangle
  append_cell(in, {9, 5, 10});             // top-right triangle
  return in;
}

// Domain [0,3]^2 tiled by a unit-wide notch (cell 0) and a U-shaped cell around it (cell 1). The U
// has an empty kernel: it is star-shaped about no point.
MeshInput u_tiling() {
  MeshInput in{Rectangle(0, 0, 3, 3),
               {Point(0, 0), Point(3, 0), Point(3, 3), Point(2, 3), Point(2, 1), Point(1, 1),
                Point(1, 3), Point(0, 3)},
               {0},
               {}};
  append_cell(in, {5, 4, 3, 6});
  append_cell(in, {0, 1, 2, 3, 4, 5, 6, 7});
  return in;
}

bool names_index(const std::string& text, int index) {
  return std::regex_search(text, std::regex("(^|[^0-9])" + std::to_string(index) + "([^0-9]|$)"));
}

std::string describe(const MeshValidationReport& r) {
  std::ostringstream os;
  os << r.defect_count << " defect(s):\n";
  for (const MeshDefect& d : r.defects)
    os << "  [" << defect_kind_name(d.kind) << " #" << d.index << "] " << d.what << "\n";
  return os.str();
}

// Expects a defect of `kind`; if `indices` is non-empty, one such defect must be about one of
// them and name it in its message.
void expect_defect(const MeshValidationReport& r, Kind kind, const std::set<int>& indices = {}) {
  EXPECT_FALSE(r.ok());
  EXPECT_GE(r.defect_count, static_cast<int>(r.defects.size()));
  bool kind_found = false, index_found = false;
  for (const MeshDefect& d : r.defects) {
    if (d.kind != kind) continue;
    kind_found = true;
    EXPECT_FALSE(d.what.empty());
    EXPECT_EQ(d.what.find('\n'), std::string::npos) << "one line: " << d.what;
    if (indices.count(d.index) && names_index(d.what, d.index)) index_found = true;
  }
  EXPECT_TRUE(kind_found) << "expected " << defect_kind_name(kind) << "; got " << describe(r);
  if (!indices.empty()) {
    std::ostringstream want;
    for (int i : indices) want << i << " ";
    EXPECT_TRUE(index_found) << "expected a " << defect_kind_name(kind) << " defect about one of { "
                             << want.str() << "} naming it; got " << describe(r);
  }
}

TEST(MeshValidator, ValidQuadGridPasses) {
  const auto r = validate_mesh(quad_grid(2, 2).build());
  EXPECT_TRUE(r.ok()) << describe(r);
  EXPECT_EQ(r.defect_count, 0);
  EXPECT_TRUE(r.defects.empty());
}

TEST(MeshValidator, ValidMixedAndStarShapedNonConvexMeshesPass) {
  // Mixed quad/triangle mesh.
  MeshInput mixed{Rectangle(0, 0, 2, 1),
                  {Point(0, 0), Point(1, 0), Point(2, 0), Point(0, 1), Point(1, 1), Point(2, 1)},
                  {0, 4, 7, 10},
                  {0, 1, 4, 3, 1, 2, 5, 1, 5, 4}};
  auto r = validate_mesh(mixed.build());
  EXPECT_TRUE(r.ok()) << describe(r);
  // A quad grid whose cells have a hanging (straight-angle) vertex: a pentagon next to a quad.
  MeshInput hanging{
      Rectangle(0, 0, 2, 1),
      {Point(0, 0), Point(1, 0), Point(2, 0), Point(0, 1), Point(1, 1), Point(2, 1), Point(1, 0.5)},
      {0, 5, 10},
      {0, 1, 6, 4, 3, 1, 2, 5, 4, 6}};
  r = validate_mesh(hanging.build());
  EXPECT_TRUE(r.ok()) << describe(r);
  // A big grid, far from the origin.
  MeshInput big = quad_grid(20, 10);
  for (Point& p : big.vertices) p = 1e-3 * p + Point(1e3, -2e3);
  big.domain = Rectangle(1e3, -2e3, 1e3 + 0.02, -2e3 + 0.01);
  r = validate_mesh(big.build());
  EXPECT_TRUE(r.ok()) << describe(r);
}

TEST(MeshValidator, EmptyMesh) {
  const PolygonMesh m(Rectangle(0, 0, 1, 1), {}, {0}, {});
  expect_defect(validate_mesh(m), Kind::empty_mesh);
}

TEST(MeshValidator, DuplicateVertex) {
  MeshInput in = quad_grid(2, 2);
  in.vertices.push_back(in.vertices[4]);  // vertex 9 duplicates vertex 4
  set_cell(in, 3, {9, 5, 8, 7});
  expect_defect(validate_mesh(in.build()), Kind::duplicate_vertex, {4, 9});
}

TEST(MeshValidator, NearlyDuplicateVertexWithinTolerance) {
  MeshInput in = quad_grid(2, 2);
  in.vertices.push_back(in.vertices[4] + Point(1e-11, 0));
  set_cell(in, 3, {9, 5, 8, 7});
  expect_defect(validate_mesh(in.build()), Kind::duplicate_vertex, {4, 9});
}

TEST(MeshValidator, UnreferencedVertex) {
  MeshInput in = quad_grid(2, 2);
  in.vertices.emplace_back(0.5, 0.5);  // vertex 9, used by no cell
  const auto r = validate_mesh(in.build());
  expect_defect(r, Kind::unreferenced_vertex, {9});
  EXPECT_EQ(r.defect_count, 1) << describe(r);
}

TEST(MeshValidator, RepeatedVertexInCell) {
  // A pinched (figure-eight) cell on [0,2]^2 visiting vertex 2 twice.
  MeshInput in{Rectangle(0, 0, 2, 2),
               {Point(0, 0), Point(2, 0), Point(1, 1), Point(2, 2), Point(0, 2)},
               {0},
               {}};
  append_cell(in, {0, 1, 2, 3, 4, 2});
  expect_defect(validate_mesh(in.build()), Kind::repeated_vertex_in_cell, {0});
}

TEST(MeshValidator, ClockwiseCell) {
  MeshInput in = quad_grid(2, 2);
  set_cell(in, 2, {6, 7, 4, 3});  // cell 2 reversed
  expect_defect(validate_mesh(in.build()), Kind::clockwise_cell, {2});
}

TEST(MeshValidator, ZeroAreaCell) {
  // 2 x 2 grid plus a fifth "cell" (0,1,2) along the bottom side: three collinear vertices.
  MeshInput in = quad_grid(2, 2);
  append_cell(in, {0, 1, 2});
  expect_defect(validate_mesh(in.build()), Kind::zero_area_cell, {4});
}

TEST(MeshValidator, SelfIntersectingCell) {
  // Cell 1 of a 1 x 2 strip is a bow-tie with positive signed area: (1,0) (2,0) (1.2,1) (1.8,1).
  MeshInput in{Rectangle(0, 0, 2, 1),
               {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1), Point(2, 0), Point(1.2, 1),
                Point(1.8, 1)},
               {0},
               {}};
  append_cell(in, {0, 1, 2, 3});
  append_cell(in, {1, 4, 5, 6});
  expect_defect(validate_mesh(in.build()), Kind::self_intersecting_cell, {1});
}

TEST(MeshValidator, NotStarShapedUShapedCell) {
  const auto r = validate_mesh(u_tiling().build());
  expect_defect(r, Kind::not_star_shaped, {1});
  // Nothing else is wrong with this tiling.
  for (const MeshDefect& d : r.defects) EXPECT_EQ(d.kind, Kind::not_star_shaped) << d.what;
}

TEST(MeshValidator, NotStarShapedAboutCentroidArrowCell) {
  // The element layer fans every cell from its centroid; the arrow's centroid fan is inverted.
  const auto r = validate_mesh(arrow_tiling().build());
  expect_defect(r, Kind::not_star_shaped, {2});
  for (const MeshDefect& d : r.defects) EXPECT_EQ(d.kind, Kind::not_star_shaped) << d.what;
}

TEST(MeshValidator, ArrowTilingIsOtherwiseConsistent) {
  // Guard for the test above: the tiling itself is conforming and covers the domain.
  const PolygonMesh m = arrow_tiling().build();
  EXPECT_TRUE(m.topology_defects().empty());
  EXPECT_DOUBLE_EQ(m.total_area(), 4.0);
  for (const MeshEdge& e : m.edges())
    if (e.on_boundary()) {
      EXPECT_NE(e.side, Side::none) << e.v0 << "-" << e.v1;
    }
}

TEST(MeshValidator, CellOutsideDomain) {
  // 2 x 1 strip on [0,2] x [0,1] whose bottom-right vertex (index 2) is moved to x = 2.5.
  MeshInput in = quad_grid(2, 1);
  in.vertices[2] = Point(2.5, 0);
  expect_defect(validate_mesh(in.build()), Kind::cell_outside_domain, {1});
}

TEST(MeshValidator, NonManifoldEdge) {
  // Edge 1-4 of a 2 x 1 strip is also used by a third cell, the triangle (6, 1, 4).
  MeshInput in = quad_grid(2, 1);
  in.vertices.emplace_back(0.5, 0.5);  // vertex 6
  append_cell(in, {6, 1, 4});
  const auto r = validate_mesh(in.build());
  expect_defect(r, Kind::non_manifold_edge);
  bool names_third_cell = false;
  for (const MeshDefect& d : r.defects)
    if (d.kind == Kind::non_manifold_edge && names_index(d.what, 2)) names_third_cell = true;
  EXPECT_TRUE(names_third_cell) << describe(r);
}

TEST(MeshValidator, InconsistentOrientation) {
  // Quad (0,1,4,3) of a 2 x 1 strip and a triangle (0,1,4) both traverse 0 -> 1 and 1 -> 4.
  MeshInput in = quad_grid(2, 1);
  append_cell(in, {0, 1, 4});
  const auto r = validate_mesh(in.build());
  expect_defect(r, Kind::inconsistent_orientation);
  bool names_cells = false;
  for (const MeshDefect& d : r.defects)
    if (d.kind == Kind::inconsistent_orientation && names_index(d.what, 0) &&
        names_index(d.what, 2))
      names_cells = true;
  EXPECT_TRUE(names_cells) << describe(r);
}

TEST(MeshValidator, InteriorHoleGivesBoundaryEdgesOffDomainAndAreaMismatch) {
  // 3 x 3 grid with the middle cell (index 4, vertices 5 6 10 9) removed.
  MeshInput in = quad_grid(3, 3);
  MeshInput holed{in.domain, in.vertices, {0}, {}};
  for (int c = 0; c < 9; ++c) {
    if (c == 4) continue;
    append_cell(holed, std::vector<int>(in.cells.begin() + in.offsets[c],
                                        in.cells.begin() + in.offsets[c + 1]));
  }
  const PolygonMesh m = holed.build();
  std::set<int> hole_edges;
  for (int e = 0; e < m.num_edges(); ++e) {
    const std::set<int> ends{m.edge(e).v0, m.edge(e).v1};
    if (ends == std::set<int>{5, 6} || ends == std::set<int>{6, 10} ||
        ends == std::set<int>{9, 10} || ends == std::set<int>{5, 9})
      hole_edges.insert(e);
  }
  ASSERT_EQ(hole_edges.size(), 4u);
  const auto r = validate_mesh(m);
  expect_defect(r, Kind::boundary_edge_off_domain, hole_edges);
  expect_defect(r, Kind::area_mismatch);
  int off = 0;
  for (const MeshDefect& d : r.defects) off += d.kind == Kind::boundary_edge_off_domain;
  EXPECT_EQ(off, 4) << describe(r);
}

TEST(MeshValidator, MissingCornerCellGivesHole) {
  // 2 x 2 grid without its top-right cell; vertex 8 (the corner) removed as well.
  MeshInput in = quad_grid(2, 2);
  in.vertices.pop_back();
  in.cells.resize(12);
  in.offsets.pop_back();
  const auto r = validate_mesh(in.build());
  expect_defect(r, Kind::boundary_edge_off_domain);
  expect_defect(r, Kind::area_mismatch);
}

TEST(MeshValidator, OverlapGivesAreaMismatch) {
  // One cell covering the whole domain plus a triangle on top of it.
  MeshInput in{Rectangle(0, 0, 1, 1),
               {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1), Point(0.2, 0.2),
                Point(0.6, 0.2), Point(0.2, 0.6)},
               {0},
               {}};
  append_cell(in, {0, 1, 2, 3});
  append_cell(in, {4, 5, 6});
  expect_defect(validate_mesh(in.build()), Kind::area_mismatch);
}

TEST(MeshValidator, OverlapByFoldedInteriorVertexIsCaught) {
  // Moving vertex 5 = (1,1) of a 3 x 3 grid to (2.5, 2.5) folds its patch over cell 8: the
  // signed areas still sum to the domain area, so the fold must show up as an inverted cell 4.
  MeshInput in = quad_grid(3, 3);
  in.vertices[5] = Point(2.5, 2.5);
  const PolygonMesh m = in.build();
  EXPECT_NEAR(m.total_area(), 9.0, 1e-12);
  expect_defect(validate_mesh(m), Kind::clockwise_cell, {4});
}

TEST(MeshValidator, SummaryHasOneLinePerDefectAndTruncates) {
  MeshInput in = quad_grid(2, 2);
  for (int k = 0; k < 30; ++k) in.vertices.emplace_back(0.05 + 0.01 * k, 0.5);  // 30 unused
  MeshValidationOptions options;
  options.max_reported = 5;
  const auto r = validate_mesh(in.build(), options);
  EXPECT_EQ(r.defect_count, 30) << describe(r);
  EXPECT_EQ(r.defects.size(), 5u);
  const std::string s = r.summary();
  EXPECT_NE(s.find("25"), std::string::npos) << "tail should say how many more: " << s;
  const auto full = validate_mesh(in.build());
  EXPECT_EQ(full.defect_count, 30);
  EXPECT_EQ(full.defects.size(), 30u);
  const std::string fs = full.summary();
  const auto lines =
      std::count(fs.begin(), fs.end(), '\n') + (fs.empty() || fs.back() == '\n' ? 0 : 1);
  EXPECT_EQ(lines, 30) << fs;
}

TEST(MeshValidator, DefectKindNamesAreDistinct) {
  std::set<std::string> names;
  for (Kind k : {Kind::empty_mesh, Kind::duplicate_vertex, Kind::unreferenced_vertex,
                 Kind::repeated_vertex_in_cell, Kind::clockwise_cell, Kind::zero_area_cell,
                 Kind::self_intersecting_cell, Kind::not_star_shaped, Kind::cell_outside_domain,
                 Kind::non_manifold_edge, Kind::inconsistent_orientation,
                 Kind::boundary_edge_off_domain, Kind::area_mismatch}) {
    const std::string n(defect_kind_name(k));
    EXPECT_FALSE(n.empty());
    EXPECT_TRUE(names.insert(n).second) << n;
  }
}

}  // namespace
}  // namespace vorodg
