// The structured families through generate_mesh: hex (regular hexagons cut to the rectangle),
// perturbed-hex (r in {0, 0.3, 0.49}), quad and tri: validity, side counts, exact area, boundary
// tags, corners, determinism and spec checks.
#include <gtest/gtest.h>

#include <ostream>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/geometry/Polygon.hpp"
#include "core/io/VtuMesh.hpp"
#include "core/mesh/MeshStatistics.hpp"
#include "core/mesh/MeshValidator.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {

// Readable gtest output for side tags.
void PrintTo(Side s, std::ostream* os) {
  *os << side_name(s);
}

namespace {

const Rectangle kHexDomain(0, 0, 8 / std::sqrt(3.0), 1);

MeshSpec spec(MeshFamily f, const Rectangle& dom, double size, double r = 0.3,
              std::uint64_t seed = 9) {
  MeshSpec s;
  s.family = f;
  s.domain = dom;
  s.size = size;
  s.perturbation = r;
  s.seed = seed;
  return s;
}

std::string first_defects(const MeshValidationReport& r) {
  std::ostringstream os;
  os << r.defect_count << " defects; first: ";
  for (std::size_t i = 0; i < std::min<std::size_t>(5, r.defects.size()); ++i)
    os << r.defects[i].what << " | ";
  return os.str();
}

void expect_valid_tiling(const PolygonMesh& m) {
  const auto report = validate_mesh(m);
  EXPECT_TRUE(report.ok()) << first_defects(report);
  const double area = m.domain().area();
  EXPECT_LT(std::abs(m.total_area() - area) / area, 1e-12);
  EXPECT_DOUBLE_EQ(m.h_avg(), std::sqrt(area / m.num_cells()));
  for (const MeshEdge& e : m.edges())
    if (e.on_boundary()) {
      EXPECT_NE(e.side, Side::none) << "edge " << e.v0 << "-" << e.v1;
    }
  const Rectangle& dom = m.domain();
  for (const Point& corner :
       {dom.lo(), Point(dom.x1(), dom.y0()), dom.hi(), Point(dom.x0(), dom.y1())})
    EXPECT_NE(std::find(m.vertices().begin(), m.vertices().end(), corner), m.vertices().end())
        << "corner " << corner.transpose() << " is not a vertex";
}

bool is_interior_cell(const PolygonMesh& m, int c) {
  for (int e : m.cell_edges(c))
    if (m.edge(e).on_boundary()) return false;
  return true;
}

TEST(HexMesh, ValidWithRegularInteriorHexagons) {
  const GeneratedMesh g = generate_mesh(spec(MeshFamily::hex, kHexDomain, 0.1));
  const PolygonMesh& m = g.mesh;
  ASSERT_GE(m.num_cells(), 100);
  ASSERT_LE(m.num_cells(), 1000);
  expect_valid_tiling(m);

  int interior = 0;
  double edge_ref = -1, area_ref = -1;
  for (int c = 0; c < m.num_cells(); ++c) {
    if (!is_interior_cell(m, c)) continue;
    ++interior;
    ASSERT_EQ(m.cell_size(c), 6) << "interior cell " << c;
    const auto pts = m.cell_points(c);
    for (int k = 0; k < 6; ++k) {
      const double len = (pts[(k + 1) % 6] - pts[k]).norm();
      if (edge_ref < 0) edge_ref = len;
      EXPECT_NEAR(len, edge_ref, 1e-12 * edge_ref) << "cell " << c << " edge " << k;
    }
    EXPECT_NEAR(polygon::min_interior_angle(pts), 2 * std::numbers::pi / 3, 1e-12) << "cell " << c;
    const double a = m.cell_area(c);
    if (area_ref < 0) area_ref = a;
    EXPECT_NEAR(a, area_ref, 1e-12 * area_ref);
  }
  EXPECT_GT(interior, m.num_cells() / 2);
  // A regular hexagon with edge s has area 3 sqrt(3)/2 s^2 and width across flats sqrt(3) s.
  EXPECT_NEAR(area_ref, 1.5 * std::sqrt(3.0) * edge_ref * edge_ref, 1e-12 * area_ref);
  // The spacing (across flats) is the requested 0.1 up to the adjustment to whole rows.
  EXPECT_NEAR(std::sqrt(3.0) * edge_ref, 0.1, 0.02);
  // A hexagon cut by one side gains at most one vertex, by two sides (a corner) at most two.
  for (int c = 0; c < m.num_cells(); ++c) {
    EXPECT_GE(m.cell_size(c), 3);
    EXPECT_LE(m.cell_size(c), 8);
  }
}

TEST(HexMesh, OtherDomainsAndSizesAreValid) {
  for (const auto& [dom, h] :
       {std::pair{Rectangle(0, 0, 4, 1), 0.1}, std::pair{Rectangle(0, 0, 1, 1), 0.23},
        std::pair{Rectangle(-2, 3, 1, 4.5), 0.17}}) {
    SCOPED_TRACE(dom.to_string() + " h=" + std::to_string(h));
    expect_valid_tiling(generate_mesh(spec(MeshFamily::hex, dom, h)).mesh);
  }
}

class PerturbedHex : public ::testing::TestWithParam<double> {};

TEST_P(PerturbedHex, ValidWithBoundaryVerticesOnTheirSidesAndCornersFixed) {
  const double r = GetParam();
  const PolygonMesh hex = generate_mesh(spec(MeshFamily::hex, kHexDomain, 0.1)).mesh;
  const PolygonMesh m = generate_mesh(spec(MeshFamily::perturbed_hex, kHexDomain, 0.1, r)).mesh;
  expect_valid_tiling(m);

  // Same topology as the hex mesh; vertices move by at most r x (hexagon edge length).
  ASSERT_EQ(m.num_vertices(), hex.num_vertices());
  ASSERT_EQ(m.offsets(), hex.offsets());
  ASSERT_EQ(m.cell_vertex_list(), hex.cell_vertex_list());
  double edge = std::numeric_limits<double>::infinity();
  for (int c = 0; c < hex.num_cells(); ++c)
    if (is_interior_cell(hex, c))
      for (int e : hex.cell_edges(c)) edge = std::min(edge, hex.edge_length(e));
  const Rectangle& dom = m.domain();
  const double tol = 1e-12 * dom.scale();
  double max_move = 0;
  int moved = 0;
  for (int v = 0; v < m.num_vertices(); ++v) {
    const Point& p0 = hex.vertex(v);
    const Point& p = m.vertex(v);
    const double move = (p - p0).norm();
    max_move = std::max(max_move, move);
    moved += move > 0;
    EXPECT_LE(move, r * edge * (1 + 1e-12) + tol) << "vertex " << v;
    const auto sides = dom.sides_near(p0, tol);
    const int nsides = sides[0] + sides[1] + sides[2] + sides[3];
    for (int k = 0; k < 4; ++k)
      if (sides[k]) {
        EXPECT_EQ(dom.distance_to_side(p, static_cast<Side>(k)), 0.0)
            << "vertex " << v << " left side " << side_name(static_cast<Side>(k));
      }
    if (nsides == 2) {
      EXPECT_EQ(p, p0) << "corner " << v << " moved";
    }
  }
  if (r == 0.0) {
    EXPECT_EQ(moved, 0);
    EXPECT_EQ(vtu_text(m), vtu_text(hex)) << "perturbed-hex with r = 0 must equal hex";
  } else {
    EXPECT_GT(moved, m.num_vertices() / 2);
    EXPECT_GT(max_move, 0.5 * r * edge) << "perturbation suspiciously small";
  }
}

INSTANTIATE_TEST_SUITE_P(R, PerturbedHex, ::testing::Values(0.0, 0.3, 0.49));

TEST(PerturbedHexSpec, DeterministicPerSeedAndRejectsBadR) {
  const auto a = generate_mesh(spec(MeshFamily::perturbed_hex, kHexDomain, 0.1, 0.3, 5)).mesh;
  const auto b = generate_mesh(spec(MeshFamily::perturbed_hex, kHexDomain, 0.1, 0.3, 5)).mesh;
  const auto c = generate_mesh(spec(MeshFamily::perturbed_hex, kHexDomain, 0.1, 0.3, 6)).mesh;
  EXPECT_EQ(vtu_text(a), vtu_text(b));
  EXPECT_NE(vtu_text(a), vtu_text(c));
  for (double r : {-0.1, 0.5, 0.7, std::numeric_limits<double>::quiet_NaN()})
    EXPECT_THROW(generate_mesh(spec(MeshFamily::perturbed_hex, kHexDomain, 0.1, r)), InputError)
        << "r = " << r;
}

TEST(QuadMesh, ValidAllCellsFourSided) {
  for (const auto& [dom, h] :
       {std::pair{Rectangle(0, 0, 4, 1), 0.1}, std::pair{Rectangle(0, 0, 1, 1), 0.3},
        std::pair{Rectangle(-1, -1, 2, 0.5), 0.07}}) {
    SCOPED_TRACE(dom.to_string() + " h=" + std::to_string(h));
    const PolygonMesh m = generate_mesh(spec(MeshFamily::quad, dom, h)).mesh;
    expect_valid_tiling(m);
    for (int c = 0; c < m.num_cells(); ++c) ASSERT_EQ(m.cell_size(c), 4) << "cell " << c;
    // All cells are rectangles of the same size, with edges near the target length.
    const double a0 = m.cell_area(0);
    for (int c = 0; c < m.num_cells(); ++c) {
      EXPECT_NEAR(m.cell_area(c), a0, 1e-12 * a0);
      EXPECT_NEAR(polygon::min_interior_angle(m.cell_points(c)), std::numbers::pi / 2, 1e-12);
    }
    // Edge lengths near the target (a whole number of cells fits each side).
    for (int e = 0; e < m.num_edges(); ++e) {
      EXPECT_LE(m.edge_length(e), 1.5 * h);
      EXPECT_GE(m.edge_length(e), 0.5 * h);
    }
  }
  // 4 x 1 with h = 0.1 is exactly 40 x 10.
  EXPECT_EQ(generate_mesh(spec(MeshFamily::quad, Rectangle(0, 0, 4, 1), 0.1)).mesh.num_cells(),
            400);
}

TEST(TriMesh, ValidAllCellsTrianglesEveryBoundaryEdgeTagged) {
  const Rectangle dom(0, 0, 4, 1);
  const GeneratedMesh g = generate_mesh(spec(MeshFamily::tri, dom, 0.1, 0.3, 3));
  const PolygonMesh& m = g.mesh;
  ASSERT_GT(m.num_cells(), 100);
  expect_valid_tiling(m);
  for (int c = 0; c < m.num_cells(); ++c) ASSERT_EQ(m.cell_size(c), 3) << "cell " << c;
  int boundary = 0;
  for (const MeshEdge& e : m.edges())
    if (e.on_boundary()) {
      ++boundary;
      ASSERT_NE(e.side, Side::none);
    }
  EXPECT_GT(boundary, 0);
  // Euler: V - E + F = 1 for a triangulated disk.
  EXPECT_EQ(m.num_vertices() - m.num_edges() + m.num_cells(), 1);
  // Seeds are at least d apart: no edge shorter than d.
  for (int e = 0; e < m.num_edges(); ++e) EXPECT_GE(m.edge_length(e), 0.1 * (1 - 1e-12));
  // Deterministic.
  EXPECT_EQ(vtu_text(m), vtu_text(generate_mesh(spec(MeshFamily::tri, dom, 0.1, 0.3, 3)).mesh));
}

TEST(MeshFamilyNames, ParseAndPrint) {
  EXPECT_EQ(parse_family("rcp"), MeshFamily::rcp);
  EXPECT_EQ(parse_family("hex"), MeshFamily::hex);
  EXPECT_EQ(parse_family("perturbed-hex"), MeshFamily::perturbed_hex);
  EXPECT_EQ(parse_family("tri"), MeshFamily::tri);
  EXPECT_EQ(parse_family("quad"), MeshFamily::quad);
  EXPECT_EQ(parse_family("file"), MeshFamily::file);
  for (MeshFamily f : {MeshFamily::rcp, MeshFamily::hex, MeshFamily::perturbed_hex, MeshFamily::tri,
                       MeshFamily::quad, MeshFamily::file})
    EXPECT_EQ(parse_family(std::string(family_name(f))), f);
  try {
    parse_family("voronoi");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("voronoi"), std::string::npos) << what;
    EXPECT_NE(what.find("perturbed-hex"), std::string::npos) << "should list valid names: " << what;
  }
}

TEST(StructuredSpec, RejectsNonPositiveSize) {
  for (MeshFamily f :
       {MeshFamily::hex, MeshFamily::perturbed_hex, MeshFamily::quad, MeshFamily::tri})
    for (double h : {0.0, -0.1, std::numeric_limits<double>::infinity()}) {
      EXPECT_THROW(generate_mesh(spec(f, Rectangle(0, 0, 4, 1), h)), InputError)
          << family_name(f) << " size " << h;
    }
}

}  // namespace
}  // namespace vorodg
