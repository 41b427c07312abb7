// The element table (core/element/ElementTable): per-cell fan quadrature and the shape functions
// and (corrected) gradients there, on rcp, hex, perturbed-hex (r = 0.3, 0.4), tri and quad meshes.
//   - layout: points per cell, fan points, positions; option checks; a cell that is not
//     star-shaped about its centroid is rejected naming the cell;
//   - fan quadrature: weights of every cell sum to its area (1e-13 relative) and integrate linear
//     functions exactly (first moments give the centroid);
//   - evaluate() at the quadrature points gives the table's values (and, without the correction,
//     its gradients);
//   - with the correction the discrete divergence identity
//       sum_q w_q dpsi_k/dx = 0.5 (y_k+1 - y_k-1),  sum_q w_q dpsi_k/dy = 0.5 (x_k-1 - x_k+1)
//     holds for every node of every cell to 1e-12 relative; without it the reported defect is
//     nonzero on general polygons (printed per family), zero on triangles and on regular interior
//     hexagons; the defect is reported before correction either way;
//   - moment matrices are well conditioned (smallest reciprocal condition printed);
//   - threads = 2 gives bitwise the same table as threads = 1;
//   - a table built without psi (ElementOptions::shape_values) has bitwise the same points,
//     weights, gradients and quality records, for the rk and vem families, with and without
//     congruent-cell reuse.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/element/ElementTable.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/quadrature/TriangleRule.hpp"
#include "core/util/Errors.hpp"
#include "support/ElementTestMeshes.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;

/// The boundary integral of psi_k n over the cell for edge-linear psi_k.
Eigen::Vector2d boundary_term(const PolygonMesh& m, int c, int k) {
  const auto loop = m.cell_vertices(c);
  const int n = static_cast<int>(loop.size());
  const Point& prev = m.vertex(loop[(k + n - 1) % n]);
  const Point& next = m.vertex(loop[(k + 1) % n]);
  return {0.5 * (next.y() - prev.y()), 0.5 * (prev.x() - next.x())};
}

/// Largest |sum_q w_q grad psi_k - boundary term| / h over the cell's nodes.
double divergence_gap(const ElementTable& t, int c) {
  const PolygonMesh& m = t.mesh();
  double gap = 0.0;
  for (int k = 0; k < t.num_nodes(c); ++k) {
    Eigen::Vector2d volume = Eigen::Vector2d::Zero();
    for (int q = 0; q < t.num_points(c); ++q) volume += t.weight(c, q) * t.grad(c, q, k);
    gap = std::max(gap, (volume - boundary_term(m, c, k)).cwiseAbs().maxCoeff());
  }
  return gap / cell_scale(m, c);
}

// ---------------------------------------------------------------------------------------------

TEST(ElementTable, OptionsAreChecked) {
  const PolygonMesh& mesh = mesh_of(kFamilies[5]);
  for (int points : {0, 2, 4, 7}) {
    ElementOptions o;
    o.rule_points = points;
    EXPECT_THROW((ElementTable(mesh, o)), InputError) << points << " points";
  }
  ElementOptions o;
  o.weights.degree = 3;
  EXPECT_THROW((ElementTable(mesh, o)), InputError);
  o.weights = {5, 1};
  EXPECT_THROW((ElementTable(mesh, o)), InputError);
}

TEST(ElementTable, RejectsACellNotStarShapedAboutItsCentroid) {
  // A U-shaped cell: its centroid (1.5, 1.357) lies in the notch, outside the cell.
  const Rectangle dom(0, 0, 3, 3);
  std::vector<Point> v = {{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
  std::vector<int> offsets = {0, 8};
  std::vector<int> loop = {0, 1, 2, 3, 4, 5, 6, 7};
  const PolygonMesh mesh(dom, v, offsets, loop);
  try {
    ElementTable table(mesh, ElementOptions{});
    ADD_FAILURE() << "no exception for a cell that is not star-shaped about its centroid";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cell 0"), std::string::npos) << e.what();
  }
}

TEST(ElementTable, LayoutAndPositions) {
  for (const Family& f : kFamilies)
    for (int rule : {1, 3, 6}) {
      const ElementTable& t = table_of(f, rule, true);
      const PolygonMesh& mesh = t.mesh();
      EXPECT_EQ(&mesh, &mesh_of(f));
      EXPECT_EQ(t.options().rule_points, rule);
      const TriangleRule& r = triangle_rule(rule);
      for (int c = 0; c < mesh.num_cells(); ++c) {
        const int n = mesh.cell_size(c);
        ASSERT_EQ(t.num_nodes(c), n);
        ASSERT_EQ(t.num_points(c), n * rule);
        const double h = cell_scale(mesh, c);
        std::vector<int> per_fan(n, 0);
        for (int q = 0; q < t.num_points(c); ++q) {
          const FanPoint& fp = t.fan_point(c, q);
          ASSERT_GE(fp.fan, 0);
          ASSERT_LT(fp.fan, n);
          ++per_fan[fp.fan];
          EXPECT_NE(std::find(r.bary.begin(), r.bary.end(), fp.bary), r.bary.end())
              << f.name << " cell " << c << " point " << q << " is not a point of the rule";
          EXPECT_LT((t.position(c, fp) - t.point(c, q)).norm(), 1e-14 * (1 + h))
              << f.name << " cell " << c;
          EXPECT_GT(t.weight(c, q), 0.0) << f.name << " cell " << c << " point " << q;
        }
        for (int k = 0; k < n; ++k) EXPECT_EQ(per_fan[k], rule) << f.name << " cell " << c;
      }
    }
}

// Acceptance 1 (fan part): weights sum to the cell area, linear moments are exact.
TEST(ElementTable, FanQuadratureWeightsSumToCellAreaAndIntegrateLinearsExactly) {
  for (const Family& f : kFamilies)
    for (int rule : {1, 3, 6}) {
      const ElementTable& t = table_of(f, rule, true);
      const PolygonMesh& mesh = t.mesh();
      double worst_area = 0.0, worst_moment = 0.0;
      for (int c = 0; c < mesh.num_cells(); ++c) {
        double sum = 0.0;
        Eigen::Vector2d moment = Eigen::Vector2d::Zero();
        for (int q = 0; q < t.num_points(c); ++q) {
          sum += t.weight(c, q);
          moment += t.weight(c, q) * t.point(c, q);
        }
        const double area = mesh.cell_area(c);
        worst_area = std::max(worst_area, std::abs(sum - area) / area);
        worst_moment = std::max(
            worst_moment, (moment / area - mesh.cell_centroid(c)).norm() / mesh.domain().scale());
      }
      EXPECT_LT(worst_area, 1e-13) << f.name << " " << rule << "-point rule";
      EXPECT_LT(worst_moment, 1e-13) << f.name << " " << rule << "-point rule";
    }
}

TEST(ElementTable, EvaluateAtQuadraturePointsMatchesTheTable) {
  for (const Family& f : kFamilies)
    for (bool correction : {false, true}) {
      const ElementTable& t = table_of(f, 3, correction);
      const PolygonMesh& mesh = t.mesh();
      for (int c = 0; c < mesh.num_cells(); ++c) {
        const int n = t.num_nodes(c);
        const double h = cell_scale(mesh, c);
        std::vector<double> psi(n);
        std::vector<Eigen::Vector2d> g(n);
        for (int q = 0; q < t.num_points(c); ++q) {
          t.evaluate(c, t.fan_point(c, q), psi.data(), g.data());
          for (int k = 0; k < n; ++k) {
            EXPECT_NEAR(psi[k], t.shape(c, q, k), 1e-14) << f.name << " cell " << c;
            if (!correction) {
              EXPECT_LT((g[k] - t.grad(c, q, k)).norm() * h, 1e-13) << f.name << " cell " << c;
            }
          }
        }
      }
    }
}

// Acceptance 5.
TEST(ElementTable, CorrectedGradientsSatisfyTheDiscreteDivergenceIdentity) {
  for (const Family& f : kFamilies)
    for (int rule : {1, 3, 6}) {
      const ElementTable& t = table_of(f, rule, true);
      const PolygonMesh& mesh = t.mesh();
      double worst = 0.0;
      int worst_cell = -1;
      for (int c = 0; c < mesh.num_cells(); ++c) {
        const double gap = divergence_gap(t, c);
        if (gap > worst) worst = gap, worst_cell = c;
      }
      EXPECT_LT(worst, 1e-12) << f.name << " " << rule << "-point rule, cell " << worst_cell;
    }
}

TEST(ElementTable, UncorrectedDefectIsReportedAndNonzeroOnGeneralPolygons) {
  for (const Family& f : kFamilies) {
    const ElementTable& off = table_of(f, 3, false);
    const ElementTable& on = table_of(f, 3, true);
    const PolygonMesh& mesh = off.mesh();
    double largest = 0.0, largest_measured = 0.0;
    int largest_cell = -1;
    for (int c = 0; c < mesh.num_cells(); ++c) {
      // The defect is measured before correction: same with the correction on or off, and
      // equal to what the uncorrected gradients show.
      EXPECT_EQ(off.divergence_defect(c), on.divergence_defect(c)) << f.name << " cell " << c;
      const double measured = divergence_gap(off, c);
      EXPECT_NEAR(off.divergence_defect(c) / cell_scale(mesh, c), measured, 1e-12)
          << f.name << " cell " << c;
      const double rel = off.divergence_defect(c) / cell_scale(mesh, c);
      if (rel > largest) largest = rel, largest_cell = c;
      largest_measured = std::max(largest_measured, measured);
    }
    std::cout << "[ defect ] " << f.name
              << ": largest divergence defect without correction = " << largest
              << " (relative to sqrt(cell area)), cell " << largest_cell << "\n";
    ::testing::Test::RecordProperty(std::string("largest_defect_") + f.name,
                                    std::to_string(largest));
    const std::string name = f.name;
    if (name == "rcp" || name.starts_with("perturbed-hex")) {
      EXPECT_GT(largest, 1e-6) << f.name;
    }
    if (name == "tri") {
      EXPECT_LT(largest, 1e-12) << "triangles are P1: no defect";
    }
  }
}

TEST(ElementTable, RegularInteriorHexagonsHaveNoDefect) {
  // A hexagon whose vertex patches are all full regular hexagons away from the boundary: by
  // symmetry the identity holds without correction (docs/design.md, divergence correction).
  const ElementTable& t = table_of(kFamilies[1], 3, false);
  const PolygonMesh& mesh = t.mesh();
  int checked = 0;
  double worst = 0.0;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    bool regular = mesh.cell_size(c) == 6;
    for (int v : mesh.cell_vertices(c))
      for (int d : mesh.vertex_cells(v)) {
        if (mesh.cell_size(d) != 6) regular = false;
        for (int k = 0; k < mesh.cell_size(d); ++k)
          if (mesh.neighbor(d, k) < 0) regular = false;
      }
    if (!regular) continue;
    ++checked;
    worst = std::max(worst, t.divergence_defect(c) / cell_scale(mesh, c));
  }
  std::cout << "[ defect ] hex: " << checked << " fully interior cells, largest defect " << worst
            << "\n";
  EXPECT_GT(checked, 10);
  EXPECT_LT(worst, 1e-10);
}

TEST(ElementTable, MomentMatricesAreWellConditioned) {
  for (const Family& f : kFamilies)
    for (int rule : {1, 3, 6}) {
      const ElementTable& t = table_of(f, rule, true);
      double smallest = INFINITY;
      for (int c = 0; c < t.mesh().num_cells(); ++c)
        smallest = std::min(smallest, t.min_moment_rcond(c));
      std::cout << "[ rcond ] " << f.name << " " << rule << "-point rule: smallest reciprocal "
                << "condition of the moment matrix = " << smallest << "\n";
      EXPECT_GT(smallest, 1e-6) << f.name << " " << rule << "-point rule";
      EXPECT_LE(smallest, 1.0 + 1e-12);
    }
}

// Acceptance 10.
/// Two tables of one mesh hold bitwise the same points, weights, gradients (and psi, if both
/// keep it) and quality records.
void expect_same_tables(const ElementTable& a, const ElementTable& b, const std::string& what) {
  const bool psi = a.has_shape_values() && b.has_shape_values();
  for (int c = 0; c < a.mesh().num_cells(); ++c) {
    ASSERT_EQ(a.num_points(c), b.num_points(c)) << what;
    EXPECT_EQ(a.divergence_defect(c), b.divergence_defect(c)) << what << " cell " << c;
    EXPECT_EQ(a.min_moment_rcond(c), b.min_moment_rcond(c)) << what << " cell " << c;
    for (int q = 0; q < a.num_points(c); ++q) {
      ASSERT_EQ(a.point(c, q), b.point(c, q)) << what << " cell " << c;
      ASSERT_EQ(a.weight(c, q), b.weight(c, q)) << what << " cell " << c;
      for (int k = 0; k < a.num_nodes(c); ++k) {
        if (psi) ASSERT_EQ(a.shape(c, q, k), b.shape(c, q, k)) << what << " cell " << c;
        ASSERT_EQ(a.grad(c, q, k), b.grad(c, q, k)) << what << " cell " << c;
      }
    }
  }
}

TEST(ElementTable, ThreadCountDoesNotChangeTheTable) {
  for (const Family& f : kFamilies)
    for (int rule : {1, 6}) {
      ElementOptions o;
      o.rule_points = rule;
      o.weights = {2, 1};
      o.threads = 1;
      const ElementTable one(mesh_of(f), o);
      o.threads = 2;
      const ElementTable two(mesh_of(f), o);
      expect_same_tables(one, two, f.name);
    }
}

TEST(ElementTable, WithoutShapeValuesTheRestIsTheSame) {
  for (const Family& f : kFamilies)
    for (ElementFamily family : {ElementFamily::rk, ElementFamily::vem})
      for (bool reuse : {true, false}) {
        ElementOptions o;
        o.family = family;
        o.reuse_congruent = reuse;
        const ElementTable with(mesh_of(f), o);
        o.shape_values = false;
        const ElementTable without(mesh_of(f), o);
        EXPECT_TRUE(with.has_shape_values());
        EXPECT_FALSE(without.has_shape_values());
        expect_same_tables(with, without, f.name);
      }
}

}  // namespace
}  // namespace vorodg
