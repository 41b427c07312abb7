// CrackGraph (fracture/CrackGraph):
//   - quad strip [0,4] x [0,1] (h = 0.25): k full vertical cross-sections are k components,
//     each touching the bottom and the top (they span the body vertically, not horizontally);
//     a cross-section cut only up to y = 0.5 touches the bottom only and does not span;
//   - an rcp mesh of [0,2] x [0,1] (d = 0.1, seed 17) cut along the cell faces nearest x = 1
//     is one component from bottom to top; the same cut restricted to y < 0.5 spans nothing;
//   - an uncracked mesh has no component, and vertices off the crack belong to none.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Errors.hpp"
#include "fracture/CrackGraph.hpp"

namespace vorodg {
namespace {

PolygonMesh make(MeshFamily family, const Rectangle& domain, double size) {
  MeshSpec spec;
  spec.family = family;
  spec.domain = domain;
  spec.size = size;
  spec.seed = 17;
  return generate_mesh(spec).mesh;
}

const PolygonMesh& strip() {
  static const PolygonMesh m = make(MeshFamily::quad, Rectangle(0.0, 0.0, 4.0, 1.0), 0.25);
  return m;
}

const PolygonMesh& rcp() {
  static const PolygonMesh m = make(MeshFamily::rcp, Rectangle(0.0, 0.0, 2.0, 1.0), 0.1);
  return m;
}

/// Interior edges on the line x = x with both ends at y <= y_max.
std::vector<char> section(const PolygonMesh& mesh, const std::vector<double>& xs,
                          double y_max = 1.0) {
  std::vector<char> cut(mesh.num_edges(), 0);
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const MeshEdge& edge = mesh.edge(e);
    if (edge.on_boundary()) continue;
    const Point &a = mesh.vertex(edge.v0), &b = mesh.vertex(edge.v1);
    for (double x : xs)
      if (std::abs(a.x() - x) < 1e-12 && std::abs(b.x() - x) < 1e-12 && a.y() <= y_max + 1e-12 &&
          b.y() <= y_max + 1e-12)
        cut[e] = 1;
  }
  return cut;
}

/// Interior edges between cells whose centroids lie on either side of x = 1 and whose ends are
/// both at y <= y_max.
std::vector<char> face_cut(const PolygonMesh& mesh, double y_max = 1.0) {
  std::vector<char> cut(mesh.num_edges(), 0);
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const MeshEdge& edge = mesh.edge(e);
    if (edge.on_boundary()) continue;
    cut[e] =
        (mesh.cell_centroid(edge.cell0).x() < 1.0) != (mesh.cell_centroid(edge.cell1).x() < 1.0) &&
        mesh.vertex(edge.v0).y() <= y_max && mesh.vertex(edge.v1).y() <= y_max;
  }
  return cut;
}

TEST(CrackGraph, FullCrossSectionsSpanTheHeight) {
  const CrackGraph graph(CrackState(strip(), section(strip(), {1.0, 2.0, 3.0})));
  ASSERT_EQ(graph.num_components(), 3);
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(graph.component_edges()[k], 4);  // one edge per row of cells
    EXPECT_TRUE(graph.touches(k, Side::bottom));
    EXPECT_TRUE(graph.touches(k, Side::top));
    EXPECT_FALSE(graph.touches(k, Side::left));
  }
  EXPECT_TRUE(graph.spans(Side::bottom, Side::top));
  EXPECT_FALSE(graph.spans(Side::left, Side::right));
  EXPECT_THROW(graph.spans(Side::none, Side::top), InputError);
}

TEST(CrackGraph, PartialCrossSectionDoesNotSpan) {
  const CrackGraph graph(CrackState(strip(), section(strip(), {2.0}, 0.5)));
  ASSERT_EQ(graph.num_components(), 1);
  EXPECT_EQ(graph.component_edges()[0], 2);
  EXPECT_TRUE(graph.touches(0, Side::bottom));
  EXPECT_FALSE(graph.touches(0, Side::top));
  EXPECT_FALSE(graph.spans(Side::bottom, Side::top));
}

TEST(CrackGraph, RcpCutSpansAndItsLowerHalfDoesNot) {
  const CrackGraph full(CrackState(rcp(), face_cut(rcp())));
  EXPECT_EQ(full.num_components(), 1);
  EXPECT_TRUE(full.spans(Side::bottom, Side::top));
  EXPECT_FALSE(full.spans(Side::left, Side::right));
  const CrackGraph half(CrackState(rcp(), face_cut(rcp(), 0.5)));
  EXPECT_GE(half.num_components(), 1);
  EXPECT_FALSE(half.spans(Side::bottom, Side::top));
  EXPECT_FALSE(half.spans(Side::left, Side::right));
}

TEST(CrackGraph, NoCrackNoComponent) {
  const CrackGraph graph(CrackState(rcp(), std::vector<char>(rcp().num_edges(), 0)));
  EXPECT_EQ(graph.num_components(), 0);
  for (int v = 0; v < rcp().num_vertices(); ++v) EXPECT_EQ(graph.component(v), -1);
  EXPECT_FALSE(graph.spans(Side::bottom, Side::top));
}

}  // namespace
}  // namespace vorodg
