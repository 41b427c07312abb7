// Congruent cells (core/element/CongruentCells) and the element table's reuse of them:
//   - on a quad grid the classes are exactly the nine a grid has (the interior, four sides, four
//     corners); a grid with spacing 0.1 (not a binary fraction, so coordinates carry round-off)
//     still gives nine; a hexagon grid has few classes; an rcp mesh none shared;
//   - every value the table stores (weights, shape functions, corrected gradients, defects) and
//     the weight functions' nodal values agree with a table computed cell by cell to 1e-12 of
//     their scale, on quads and hexagons, for RK, Wachspress and the virtual element;
//   - the errors against the beam's exact solution agree to 1e-12 relative.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/element/CongruentCells.hpp"
#include "core/element/ElementTable.hpp"
#include "core/material/IsotropicElasticity.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/problem/ErrorNorms.hpp"
#include "core/problem/TimoshenkoBeam.hpp"

namespace vorodg {
namespace {

PolygonMesh make_mesh(MeshFamily family, double size) {
  MeshSpec spec;
  spec.family = family;
  spec.domain = Rectangle(0.0, -0.5, 4.0, 0.5);
  spec.size = size;
  spec.seed = 7;
  return generate_mesh(spec).mesh;
}

ElementTable table_of(const PolygonMesh& mesh, ElementFamily family, bool reuse) {
  ElementOptions o;
  o.family = family;
  o.reuse_congruent = reuse;
  return ElementTable(mesh, o);
}

TEST(CongruentCells, AQuadGridHasNineClasses) {
  for (double h : {0.125, 0.1}) {
    const PolygonMesh mesh = make_mesh(MeshFamily::quad, h);
    const CongruentCells classes(mesh);
    EXPECT_EQ(classes.num_classes(), 9) << "h = " << h;
    int largest = 0;
    for (int c = 0; c < mesh.num_cells(); ++c) largest = std::max(largest, classes.class_size(c));
    const int nx = static_cast<int>(std::lround(4.0 / h)),
              ny = static_cast<int>(std::lround(1 / h));
    EXPECT_EQ(largest, (nx - 2) * (ny - 2)) << "h = " << h;
  }
}

TEST(CongruentCells, HexagonsShareAndRcpCellsDoNot) {
  const PolygonMesh hex = make_mesh(MeshFamily::hex, 0.1);
  const CongruentCells hex_classes(hex);
  EXPECT_LT(hex_classes.num_classes(), hex.num_cells() / 4);
  const PolygonMesh rcp = make_mesh(MeshFamily::rcp, 0.1);
  EXPECT_EQ(CongruentCells(rcp).num_classes(), rcp.num_cells());
}

/// The largest difference between two tables' stored values, over the scale of those values.
void expect_same_tables(const ElementTable& a, const ElementTable& b, double tolerance) {
  const PolygonMesh& mesh = a.mesh();
  double shape = 0.0, grad = 0.0, weight = 0.0, grad_scale = 0.0;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    ASSERT_EQ(a.num_points(c), b.num_points(c));
    for (int q = 0; q < a.num_points(c); ++q) {
      weight = std::max(weight, std::abs(a.weight(c, q) - b.weight(c, q)) / mesh.cell_area(c));
      EXPECT_LE((a.point(c, q) - b.point(c, q)).norm(), 1e-14 * 4.0);
      for (int k = 0; k < a.num_nodes(c); ++k) {
        shape = std::max(shape, std::abs(a.shape(c, q, k) - b.shape(c, q, k)));
        grad = std::max(grad, (a.grad(c, q, k) - b.grad(c, q, k)).norm());
        grad_scale = std::max(grad_scale, b.grad(c, q, k).norm());
      }
    }
    EXPECT_NEAR(a.divergence_defect(c), b.divergence_defect(c),
                tolerance * std::sqrt(mesh.cell_area(c)));
  }
  EXPECT_LE(weight, tolerance);
  EXPECT_LE(shape, tolerance);
  EXPECT_LE(grad, tolerance * grad_scale);
}

TEST(CongruentCells, ReusedValuesAreTheComputedOnes) {
  for (MeshFamily mesh_family : {MeshFamily::quad, MeshFamily::hex})
    for (ElementFamily element :
         {ElementFamily::rk, ElementFamily::wachspress, ElementFamily::vem}) {
      SCOPED_TRACE(std::string(family_name(mesh_family)) + ", element " +
                   std::to_string(static_cast<int>(element)));
      const PolygonMesh mesh = make_mesh(mesh_family, 0.1);
      const ElementTable reused = table_of(mesh, element, true);
      const ElementTable computed = table_of(mesh, element, false);
      EXPECT_LT(reused.num_classes(), mesh.num_cells());
      EXPECT_EQ(computed.num_classes(), mesh.num_cells());
      expect_same_tables(reused, computed, 1e-12);
      if (element != ElementFamily::rk) continue;
      double values = 0.0;
      for (int c = 0; c < mesh.num_cells(); ++c)
        for (int k = 0; k < mesh.cell_size(c); ++k) {
          const auto a = reused.weights().values(c, k), b = computed.weights().values(c, k);
          for (std::size_t i = 0; i < a.size(); ++i)
            values = std::max(values, std::abs(a[i] - b[i]) / mesh.cell_area(c));
        }
      EXPECT_LE(values, 1e-12);  // -lap w = 1: w scales as the area
    }
}

TEST(CongruentCells, TheBeamsErrorsDoNotMove) {
  const PolygonMesh mesh = make_mesh(MeshFamily::quad, 0.1);
  const IsotropicElasticity material(1.0, 0.3, PlaneModel::stress);
  const TimoshenkoBeam beam(material, 4.0, 1.0, 1.0);
  // The exact solution's nodal values as the discrete field: its interpolation error.
  const auto nodal = [&](int c) {
    Eigen::VectorXd u(2 * mesh.cell_size(c));
    int j = 0;
    for (int v : mesh.cell_vertices(c)) u.segment<2>(2 * j++) = beam.displacement(mesh.vertex(v));
    return u;
  };
  const ErrorReport reused = compute_errors(table_of(mesh, ElementFamily::rk, true), beam, nodal);
  const ErrorReport computed =
      compute_errors(table_of(mesh, ElementFamily::rk, false), beam, nodal);
  EXPECT_NEAR(reused.l2_error, computed.l2_error, 1e-12 * computed.l2_error);
  EXPECT_NEAR(reused.energy_error, computed.energy_error, 1e-12 * computed.energy_error);
  EXPECT_GT(computed.l2_error, 0.0);
}

}  // namespace
}  // namespace vorodg
