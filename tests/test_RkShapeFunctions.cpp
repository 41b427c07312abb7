// Reproducing-kernel shape functions (core/element/RkShapeFunctions) on their own and as the
// element table delivers them, on rcp, hex, perturbed-hex (r = 0.3, 0.4), tri and quad meshes:
//   - the kernel: partition of unity, linear reproduction of values and gradients for arbitrary
//     positive weights, gradients against finite differences, independence of the cell frame,
//     the P1 triangle for three nodes;
//   - at every quadrature point of every cell (1, 3, 6 points per fan triangle, with and without
//     the divergence correction): sum psi = 1, sum psi x_I = x, sum grad psi = 0,
//     sum x_I (x) grad psi_I = I, to 1e-12 relative;
//   - Kronecker delta at the vertices, exact linearity along every cell edge, continuity across
//     interior edges (exactly on the edge and approached from inside both cells);
//   - on triangle meshes the element is the linear triangle, for every weight resolution.
#include <gtest/gtest.h>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "core/element/ElementTable.hpp"
#include "core/element/RkShapeFunctions.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/quadrature/TriangleRule.hpp"
#include "support/ElementTestMeshes.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;

// ---------------------------------------------------------------------------------------------
// Meshes and tables shared by the tests (built once).

const Family& kTri = kFamilies[4];

int local_index(std::span<const int> loop, int v) {
  return static_cast<int>(std::find(loop.begin(), loop.end(), v) - loop.begin());
}

// ---------------------------------------------------------------------------------------------
// The kernel on its own.

/// Smooth positive weights w_J(x) = (1 + J/10) exp(-|x - x_J|^2 / s^2) with exact gradients.
struct GaussianWeights {
  std::vector<Eigen::Vector2d> nodes;
  double s;
  void operator()(const Eigen::Vector2d& x, double* w, Eigen::Vector2d* g) const {
    for (std::size_t J = 0; J < nodes.size(); ++J) {
      const Eigen::Vector2d d = x - nodes[J];
      w[J] = (1.0 + 0.1 * J) * std::exp(-d.squaredNorm() / (s * s));
      g[J] = -2.0 * d / (s * s) * w[J];
    }
  }
};

std::vector<Eigen::Vector2d> irregular_pentagon() {
  return {{0.1, 0.0}, {1.3, 0.2}, {1.6, 1.1}, {0.7, 1.7}, {-0.2, 0.9}};
}
std::vector<Eigen::Vector2d> regular_hexagon() {
  std::vector<Eigen::Vector2d> p;
  for (int k = 0; k < 6; ++k)
    p.emplace_back(0.3 + 0.05 * std::cos(k * std::numbers::pi / 3),
                   -0.2 + 0.05 * std::sin(k * std::numbers::pi / 3));
  return p;
}

void check_kernel_consistency(const std::vector<Eigen::Vector2d>& nodes, const RkCellFrame& frame,
                              double s, const std::vector<Eigen::Vector2d>& points) {
  const int n = static_cast<int>(nodes.size());
  const GaussianWeights weights{nodes, s};
  std::vector<double> w(n), psi(n);
  std::vector<Eigen::Vector2d> gw(n), gpsi(n);
  for (const Eigen::Vector2d& x : points) {
    weights(x, w.data(), gw.data());
    const double rcond =
        rk_shape_functions(frame, nodes, x, w.data(), gw.data(), psi.data(), gpsi.data());
    EXPECT_GT(rcond, 0.0);
    EXPECT_LE(rcond, 1.0 + 1e-12);
    double sum = 0.0;
    Eigen::Vector2d first = Eigen::Vector2d::Zero(), gsum = Eigen::Vector2d::Zero();
    Eigen::Matrix2d G = Eigen::Matrix2d::Zero();
    for (int I = 0; I < n; ++I) {
      sum += psi[I];
      first += psi[I] * (nodes[I] - x);
      gsum += gpsi[I];
      G += (nodes[I] - frame.centre) * gpsi[I].transpose();
    }
    EXPECT_NEAR(sum, 1.0, 1e-13);
    EXPECT_LT(first.norm() / frame.scale, 1e-13);
    EXPECT_LT(gsum.norm() * frame.scale, 1e-12);
    EXPECT_LT((G - Eigen::Matrix2d::Identity()).cwiseAbs().maxCoeff(), 1e-12);
    // Gradients against central differences (weights re-evaluated at the shifted points).
    const double d = 1e-6 * frame.scale;
    std::vector<double> pp(n), pm(n);
    std::vector<Eigen::Vector2d> scratch(n);
    for (int dir = 0; dir < 2; ++dir) {
      const Eigen::Vector2d step = d * Eigen::Vector2d::Unit(dir);
      weights(x + step, w.data(), gw.data());
      rk_shape_functions(frame, nodes, x + step, w.data(), gw.data(), pp.data(), scratch.data());
      weights(x - step, w.data(), gw.data());
      rk_shape_functions(frame, nodes, x - step, w.data(), gw.data(), pm.data(), scratch.data());
      for (int I = 0; I < n; ++I)
        EXPECT_NEAR(gpsi[I][dir], (pp[I] - pm[I]) / (2 * d), 1e-6 / frame.scale)
            << "node " << I << " direction " << dir << " at " << x.transpose();
    }
  }
}

TEST(RkKernel, ReproducesLinearFieldsAndDifferentiatesCorrectly) {
  const auto pent = irregular_pentagon();
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for (const auto& p : pent) centre += p / pent.size();
  check_kernel_consistency(pent, {centre, 1.2}, 1.0,
                           {centre, {0.5, 0.4}, {1.2, 0.9}, {0.3, 1.0}, {0.8, 1.4}});
  const auto hex = regular_hexagon();
  check_kernel_consistency(hex, {{0.3, -0.2}, 0.05}, 0.06,
                           {{0.3, -0.2}, {0.31, -0.19}, {0.27, -0.21}, {0.33, -0.17}});
}

TEST(RkKernel, IndependentOfTheFrame) {
  const auto nodes = irregular_pentagon();
  const int n = static_cast<int>(nodes.size());
  const GaussianWeights weights{nodes, 1.0};
  const Eigen::Vector2d x(0.6, 0.7);
  std::vector<double> w(n), a(n), b(n);
  std::vector<Eigen::Vector2d> gw(n), ga(n), gb(n);
  weights(x, w.data(), gw.data());
  rk_shape_functions({{0.7, 0.8}, 1.0}, nodes, x, w.data(), gw.data(), a.data(), ga.data());
  rk_shape_functions({{-3.0, 5.0}, 7.5}, nodes, x, w.data(), gw.data(), b.data(), gb.data());
  for (int I = 0; I < n; ++I) {
    EXPECT_NEAR(a[I], b[I], 1e-12);
    EXPECT_LT((ga[I] - gb[I]).norm(), 1e-11);
  }
}

// A cell's node basis computed once (what ElementTable does) gives the same bits.
TEST(RkKernel, TheNodeBasisOnceGivesTheSameBits) {
  const auto nodes = irregular_pentagon();
  const int n = static_cast<int>(nodes.size());
  const GaussianWeights weights{nodes, 1.0};
  const RkCellFrame frame{{0.7, 0.8}, 1.3};
  std::vector<Eigen::Vector3d> basis(n);
  rk_node_basis(frame, nodes, basis.data());
  for (const Eigen::Vector2d& x : {Eigen::Vector2d(0.6, 0.7), Eigen::Vector2d(0.31, 0.55)}) {
    std::vector<double> w(n), a(n), b(n);
    std::vector<Eigen::Vector2d> gw(n), ga(n), gb(n);
    weights(x, w.data(), gw.data());
    const double ra = rk_shape_functions(frame, nodes, x, w.data(), gw.data(), a.data(), ga.data());
    const double rb = rk_shape_functions(frame, std::span<const Eigen::Vector3d>(basis), x,
                                         w.data(), gw.data(), b.data(), gb.data());
    EXPECT_EQ(ra, rb);
    for (int I = 0; I < n; ++I) {
      EXPECT_EQ(a[I], b[I]);
      EXPECT_EQ(ga[I], gb[I]);
    }
  }
}

TEST(RkKernel, ThreeNodesGiveTheLinearTriangleForAnyWeights) {
  const std::vector<Eigen::Vector2d> tri = {{0.2, 0.1}, {1.1, 0.3}, {0.4, 0.9}};
  const double area2 =
      (tri[1] - tri[0]).x() * (tri[2] - tri[0]).y() - (tri[1] - tri[0]).y() * (tri[2] - tri[0]).x();
  const Eigen::Vector2d x = 0.2 * tri[0] + 0.5 * tri[1] + 0.3 * tri[2];
  const double lambda[3] = {0.2, 0.5, 0.3};
  const double w[3] = {0.3, 2.0, 0.01};
  const Eigen::Vector2d gw[3] = {{1.0, -3.0}, {0.2, 7.0}, {-5.0, 0.5}};
  double psi[3];
  Eigen::Vector2d g[3];
  rk_shape_functions({{0.5, 0.4}, 0.6}, tri, x, w, gw, psi, g);
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector2d e = tri[(k + 2) % 3] - tri[(k + 1) % 3];
    const Eigen::Vector2d exact_grad(-e.y() / area2, e.x() / area2);
    EXPECT_NEAR(psi[k], lambda[k], 1e-13);
    EXPECT_LT((g[k] - exact_grad).norm(), 1e-12) << "node " << k;
  }
}

// ---------------------------------------------------------------------------------------------
// Acceptance 2: consistency at every quadrature point of every cell.

TEST(RkShapeFunctions, PartitionOfUnityAndLinearReproductionAtQuadraturePoints) {
  for (const Family& f : kFamilies)
    for (int rule : {1, 3, 6})
      for (bool correction : {false, true}) {
        const ElementTable& t = table_of(f, rule, correction);
        const PolygonMesh& mesh = t.mesh();
        double worst[4] = {0, 0, 0, 0};
        for (int c = 0; c < mesh.num_cells(); ++c) {
          const int n = t.num_nodes(c);
          const double h = cell_scale(mesh, c);
          const Point xc = mesh.cell_centroid(c);
          for (int q = 0; q < t.num_points(c); ++q) {
            const Point& x = t.point(c, q);
            double sum = 0.0;
            Eigen::Vector2d first = Eigen::Vector2d::Zero(), gsum = Eigen::Vector2d::Zero();
            Eigen::Matrix2d G = Eigen::Matrix2d::Zero();
            for (int k = 0; k < n; ++k) {
              const Point& xk = mesh.vertex(mesh.cell_vertices(c)[k]);
              sum += t.shape(c, q, k);
              first += t.shape(c, q, k) * (xk - x);
              gsum += t.grad(c, q, k);
              G += (xk - xc) * t.grad(c, q, k).transpose();
            }
            worst[0] = std::max(worst[0], std::abs(sum - 1.0));
            worst[1] = std::max(worst[1], first.norm() / h);
            worst[2] = std::max(worst[2], gsum.norm() * h);
            worst[3] = std::max(worst[3], (G - Eigen::Matrix2d::Identity()).cwiseAbs().maxCoeff());
          }
        }
        const std::string what = std::string(f.name) + ", " + std::to_string(rule) +
                                 "-point rule, correction " + (correction ? "on" : "off");
        EXPECT_LT(worst[0], 1e-12) << what << ": |sum psi - 1|";
        EXPECT_LT(worst[1], 1e-12) << what << ": |sum psi (x_I - x)| / h";
        EXPECT_LT(worst[2], 1e-12) << what << ": |sum grad psi| h";
        EXPECT_LT(worst[3], 1e-12) << what << ": |sum x_I (x) grad psi_I - I|";
      }
}

// ---------------------------------------------------------------------------------------------
// Acceptance 3: Kronecker delta, edge linearity, continuity.

TEST(RkShapeFunctions, KroneckerDeltaAtVertices) {
  for (const Family& f : kFamilies) {
    const ElementTable& t = table_of(f, 3, true);
    const PolygonMesh& mesh = t.mesh();
    for (int c = 0; c < mesh.num_cells(); ++c) {
      const int n = t.num_nodes(c);
      std::vector<double> psi(n);
      std::vector<Eigen::Vector2d> g(n);
      for (int k = 0; k < n; ++k) {
        // Vertex k as the first vertex of fan k and as the second vertex of fan k-1.
        for (const FanPoint& at :
             {FanPoint{k, {0.0, 1.0, 0.0}}, FanPoint{(k + n - 1) % n, {0.0, 0.0, 1.0}}}) {
          EXPECT_LT((t.position(c, at) - mesh.vertex(mesh.cell_vertices(c)[k])).norm(), 1e-15 * 4);
          t.evaluate(c, at, psi.data(), g.data());
          for (int j = 0; j < n; ++j)
            EXPECT_NEAR(psi[j], j == k ? 1.0 : 0.0, 1e-12)
                << f.name << " cell " << c << " vertex " << k << " (fan " << at.fan << "): psi_"
                << j;
        }
      }
    }
  }
}

TEST(RkShapeFunctions, LinearAlongEveryCellEdge) {
  for (const Family& f : kFamilies) {
    const ElementTable& t = table_of(f, 3, true);
    const PolygonMesh& mesh = t.mesh();
    for (int c = 0; c < mesh.num_cells(); ++c) {
      const int n = t.num_nodes(c);
      std::vector<double> psi(n);
      std::vector<Eigen::Vector2d> g(n);
      for (int k = 0; k < n; ++k)
        for (double s : {0.1, 0.25, 0.5, 0.75, 0.9}) {
          t.evaluate(c, FanPoint{k, {0.0, 1.0 - s, s}}, psi.data(), g.data());
          for (int j = 0; j < n; ++j) {
            const double expected = j == k ? 1.0 - s : j == (k + 1) % n ? s : 0.0;
            EXPECT_NEAR(psi[j], expected, 1e-12)
                << f.name << " cell " << c << " edge " << k << " t " << s << ": psi_" << j;
          }
          for (int j = 0; j < n; ++j) EXPECT_TRUE(g[j].allFinite()) << f.name << " cell " << c;
        }
    }
  }
}

/// Linear interpolation between the edge's end points is the exact edge limit; from just inside
/// the cell the interior formula must approach it (the weights of the other nodes vanish on the
/// edge), linearly in the distance. Measured at centroid coordinates 1e-6 and 1e-8.
double edge_limit_deviation(const ElementTable& t, double eps) {
  const PolygonMesh& mesh = t.mesh();
  double worst = 0.0;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const int n = t.num_nodes(c);
    std::vector<double> psi(n);
    std::vector<Eigen::Vector2d> g(n);
    for (int k = 0; k < n; ++k)
      for (double s : {0.25, 0.5, 0.75}) {
        t.evaluate(c, FanPoint{k, {eps, (1 - eps) * (1.0 - s), (1 - eps) * s}}, psi.data(),
                   g.data());
        for (int j = 0; j < n; ++j) {
          const double expected = j == k ? 1.0 - s : j == (k + 1) % n ? s : 0.0;
          worst = std::max(worst, std::abs(psi[j] - expected));
        }
      }
  }
  return worst;
}

TEST(RkShapeFunctions, InteriorValuesApproachTheEdgeLimit) {
  for (const Family& f : kFamilies) {
    const ElementTable& t = table_of(f, 3, true);
    const double d6 = edge_limit_deviation(t, 1e-6), d8 = edge_limit_deviation(t, 1e-8);
    std::cout << "[ rk ] " << f.name << ": largest |psi - edge limit| at centroid coordinate "
              << "1e-6: " << d6 << ", 1e-8: " << d8 << "\n";
    EXPECT_LT(d6, 1e-2) << f.name;  // ~ |grad psi| x distance; the real check is the next line
    EXPECT_LT(d8, 0.02 * d6 + 1e-10) << f.name << ": not converging linearly to the edge limit";
  }
}

/// Largest jump of the two shared vertices' psi across interior edges, evaluated from inside both
/// cells at centroid coordinate eps; exactly on the edge (eps = 0) everything must agree.
double edge_jump(const ElementTable& t, double eps) {
  const PolygonMesh& mesh = t.mesh();
  double worst = 0.0;
  for (const MeshEdge& e : mesh.edges()) {
    if (e.on_boundary()) continue;
    const auto l0 = mesh.cell_vertices(e.cell0), l1 = mesh.cell_vertices(e.cell1);
    const int n0 = static_cast<int>(l0.size()), n1 = static_cast<int>(l1.size());
    const int k0 = local_index(l0, e.v0), k1 = local_index(l1, e.v1);
    EXPECT_EQ(l0[(k0 + 1) % n0], e.v1);
    EXPECT_EQ(l1[(k1 + 1) % n1], e.v0);
    std::vector<double> p0(n0), p1(n1);
    std::vector<Eigen::Vector2d> g0(n0), g1(n1);
    const double scale = mesh.edge_length(static_cast<int>(&e - mesh.edges().data()));
    for (double s : {0.0, 0.2, 0.5, 0.8, 1.0}) {  // s: fraction from v0 towards v1
      if (eps > 0.0 && (s == 0.0 || s == 1.0)) continue;
      const FanPoint a{k0, {eps, (1 - eps) * (1.0 - s), (1 - eps) * s}};
      const FanPoint b{k1, {eps, (1 - eps) * s, (1 - eps) * (1.0 - s)}};
      if (eps == 0.0) {
        EXPECT_LT((t.position(e.cell0, a) - t.position(e.cell1, b)).norm(), 1e-14 * (1 + scale));
      }
      t.evaluate(e.cell0, a, p0.data(), g0.data());
      t.evaluate(e.cell1, b, p1.data(), g1.data());
      for (int j = 0; j < n0; ++j) {
        const int j1 = local_index(l1, l0[j]);
        const bool shared = j1 < n1;
        if (eps == 0.0 && !shared) worst = std::max(worst, std::abs(p0[j]));
        if (shared && (eps == 0.0 || j == k0 || j == (k0 + 1) % n0))
          worst = std::max(worst, std::abs(p0[j] - p1[j1]));
      }
    }
  }
  return worst;
}

TEST(RkShapeFunctions, ContinuousAcrossInteriorEdges) {
  for (const Family& f : kFamilies) {
    const ElementTable& t = table_of(f, 3, true);
    const double on_edge = edge_jump(t, 0.0), d6 = edge_jump(t, 1e-6), d8 = edge_jump(t, 1e-8);
    std::cout << "[ rk ] " << f.name << ": largest jump of the shared vertices' psi across an "
              << "interior edge: on the edge " << on_edge << ", from inside at centroid coordinate "
              << "1e-6: " << d6 << ", 1e-8: " << d8 << "\n";
    EXPECT_LT(on_edge, 1e-12) << f.name;
    EXPECT_LT(d6, 1e-3) << f.name;
    EXPECT_LT(d8, 0.02 * d6 + 1e-10) << f.name << ": the jump does not vanish at the edge";
  }
}

// ---------------------------------------------------------------------------------------------
// Acceptance 4: triangles give the linear triangle.

TEST(RkShapeFunctions, TriangleMeshGivesTheLinearTriangle) {
  const PolygonMesh& mesh = mesh_of(kTri);
  for (int c = 0; c < mesh.num_cells(); ++c) ASSERT_EQ(mesh.cell_size(c), 3);
  for (int refinement : {0, 1, 2})
    for (int degree : {1, 2})
      for (int rule : {1, 3, 6})
        for (bool correction : {true, false}) {
          const ElementTable& t = table_of(kTri, rule, correction, {refinement, degree});
          double worst_psi = 0.0, worst_grad = 0.0;
          int worst_cell = -1;
          for (int c = 0; c < mesh.num_cells(); ++c) {
            const double before = worst_grad;
            const auto loop = mesh.cell_vertices(c);
            Eigen::Matrix3d T;  // rows: 1, x, y; columns: vertices
            for (int k = 0; k < 3; ++k) T.col(k) << 1.0, mesh.vertex(loop[k]);
            const Eigen::Matrix3d Tinv = T.inverse();  // lambda = Tinv (1, x, y)
            const double h = cell_scale(mesh, c);
            auto check = [&](const Point& x, const double* psi, const Eigen::Vector2d* g) {
              const Eigen::Vector3d lambda = Tinv * Eigen::Vector3d(1.0, x.x(), x.y());
              for (int k = 0; k < 3; ++k) {
                worst_psi = std::max(worst_psi, std::abs(psi[k] - lambda[k]));
                const Eigen::Vector2d exact(Tinv(k, 1), Tinv(k, 2));
                worst_grad = std::max(worst_grad, (g[k] - exact).norm() * h);
              }
            };
            for (int q = 0; q < t.num_points(c); ++q) {
              double psi[3];
              Eigen::Vector2d g[3];
              for (int k = 0; k < 3; ++k) psi[k] = t.shape(c, q, k), g[k] = t.grad(c, q, k);
              check(t.point(c, q), psi, g);
            }
            // And anywhere through evaluate() (uncorrected gradients).
            for (int fan = 0; fan < 3; ++fan)
              for (const Eigen::Vector3d& bary :
                   {Eigen::Vector3d(0.7, 0.2, 0.1), Eigen::Vector3d(0.05, 0.05, 0.9),
                    Eigen::Vector3d(0.3, 0.35, 0.35)}) {
                double psi[3];
                Eigen::Vector2d g[3];
                t.evaluate(c, FanPoint{fan, bary}, psi, g);
                check(t.position(c, FanPoint{fan, bary}), psi, g);
              }
            if (worst_grad > before) worst_cell = c;
          }
          const std::string what = "refinement " + std::to_string(refinement) + " degree " +
                                   std::to_string(degree) + " rule " + std::to_string(rule) +
                                   " correction " + (correction ? "on" : "off");
          EXPECT_LT(worst_psi, 1e-12) << what;
          EXPECT_LT(worst_grad, 1e-12)
              << what << ": worst cell " << worst_cell << " (largest angle "
              << largest_angle_degrees(mesh, worst_cell) << " deg, smallest moment rcond "
              << t.min_moment_rcond(worst_cell) << ")";
        }
}

}  // namespace
}  // namespace vorodg
