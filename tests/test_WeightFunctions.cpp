// Nodal weight functions of the RK polygon element (core/element/WeightFunctions) and the fan
// lattice they live on (FanLattice.hpp, LatticeBasis.hpp). Checks, on rcp, hex, perturbed-hex
// (r = 0.3, 0.4), tri and quad meshes:
//   - the lattice numbering is a bijection and points are located in the right sub-triangle;
//   - w_k is held at exactly zero on the Dirichlet part of its patch (every lattice node on a cell
//     edge not incident to vertex k, the other vertices included), positive at its own vertex and
//     on the Neumann part (domain-boundary edges at k);
//   - w_k > 0 at every quadrature point (1, 3, 6 points per fan triangle) for every node k;
//   - the patch problem is conforming: neighbouring cells hold the same nodal values on a shared
//     edge and at the vertex;
//   - evaluate() interpolates the nodal values and its gradient matches finite differences;
//   - results with 2 threads are bitwise identical to 1 thread (dense and sparse patch solves);
//   - the condensed cells (small lattices) give the per-patch solution to round-off;
//   - option checking.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/element/FanLattice.hpp"
#include "core/element/LatticeBasis.hpp"
#include "core/element/WeightFunctions.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/quadrature/TriangleRule.hpp"
#include "core/util/Errors.hpp"
#include "support/ElementTestMeshes.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;

const WeightFunctionOptions kOptionSets[] = {{0, 1}, {1, 1}, {2, 1}, {0, 2}, {1, 2}};

std::string label(const Family& f, const WeightFunctionOptions& o) {
  return std::string(f.name) + " refinement " + std::to_string(o.refinement) + " degree " +
         std::to_string(o.degree);
}

/// Scale of a cell's weight functions: -lap w = 1 gives w ~ (cell size)^2.
double weight_scale(const PolygonMesh& m, int c) {
  return m.cell_area(c);
}

// ---------------------------------------------------------------------------------------------
// The lattice.

TEST(FanLattice, NumberingIsABijectionWithSharedSpokesAndVertices) {
  for (int n : {3, 4, 6, 8})
    for (int N : {1, 2, 3, 4, 8}) {
      const FanLattice lat(n, N);
      std::vector<int> hits(lat.node_count(), 0);
      for (int k = 0; k < n; ++k)
        for (int i = 0; i <= N; ++i)
          for (int j = 0; i + j <= N; ++j) {
            const int node = lat.node(k, i, j);
            ASSERT_GE(node, 0);
            ASSERT_LT(node, lat.node_count());
            ++hits[node];
          }
      // Centroid: in all n fans. Vertices and spoke nodes: in two fans. Edge and interior
      // nodes: in one.
      for (int node = 0; node < lat.node_count(); ++node) {
        int expected = 1;
        if (node == 0)
          expected = n;
        else if (lat.is_vertex(node))
          expected = 2;
        else if (node < 1 + n + n * (N - 1))
          expected = 2;  // spokes
        EXPECT_EQ(hits[node], expected) << "n " << n << " N " << N << " node " << node;
      }
      for (int k = 0; k < n; ++k) {
        EXPECT_EQ(lat.node(k, N, 0), 1 + k);
        EXPECT_EQ(lat.node(k, 0, N), 1 + (k + 1) % n);
        for (int t = 1; t < N; ++t) {
          EXPECT_EQ(lat.node(k, N - t, t), lat.edge_node(k, t));
          EXPECT_EQ(lat.edge_of(lat.edge_node(k, t)), k);
          EXPECT_EQ(lat.node(k, t, 0), lat.spoke_node(k, t));
          EXPECT_EQ(lat.node(k, 0, t), lat.spoke_node((k + 1) % n, t));
          EXPECT_EQ(lat.edge_of(lat.spoke_node(k, t)), -1);
        }
      }
    }
}

TEST(FanLattice, LocateFindsTheContainingSubTriangle) {
  for (int m : {1, 2, 4}) {
    for (int s = 0; s < 400; ++s) {
      // A deterministic spread of points over the triangle, including its edges.
      const double u = (s % 20) / 19.0, v = (s / 20) / 19.0;
      if (u + v > 1.0) continue;
      const Eigen::Vector3d bary(1.0 - u - v, u, v);
      const LatticeLocation loc = locate_in_lattice(bary, m);
      ASSERT_GE(loc.a, 0);
      ASSERT_GE(loc.b, 0);
      ASSERT_LE(loc.a + loc.b, m - 1);
      if (!loc.up) {
        ASSERT_LE(loc.a + loc.b, m - 2);
      }
      EXPECT_GE(loc.xi, -1e-12);
      EXPECT_GE(loc.eta, -1e-12);
      EXPECT_LE(loc.xi + loc.eta, 1.0 + 1e-12);
      // Rebuild the lattice coordinates from the location.
      const double ru = loc.up ? loc.a + loc.xi : loc.a + 1 - loc.xi;
      const double rv = loc.up ? loc.b + loc.eta : loc.b + 1 - loc.eta;
      EXPECT_NEAR(ru, m * u, 1e-12) << "m " << m << " point (" << u << ", " << v << ")";
      EXPECT_NEAR(rv, m * v, 1e-12) << "m " << m << " point (" << u << ", " << v << ")";
    }
  }
}

TEST(LatticeBasis, PartitionOfUnityAndNodalInterpolation) {
  for (int degree : {1, 2}) {
    const int count = degree == 1 ? 3 : 6;
    const double nodes[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
    for (int a = 0; a < count; ++a) {
      double phi[6], dphi[6][2];
      lattice_basis(degree, nodes[a][0], nodes[a][1], phi, dphi);
      double sum = 0.0, dsum[2] = {0, 0};
      for (int i = 0; i < count; ++i) {
        EXPECT_NEAR(phi[i], i == a ? 1.0 : 0.0, 1e-15) << "degree " << degree;
        sum += phi[i];
        dsum[0] += dphi[i][0];
        dsum[1] += dphi[i][1];
      }
      EXPECT_NEAR(sum, 1.0, 1e-15);
      EXPECT_NEAR(dsum[0], 0.0, 1e-14);
      EXPECT_NEAR(dsum[1], 0.0, 1e-14);
    }
  }
}

// ---------------------------------------------------------------------------------------------
// The weight functions.

TEST(WeightFunctions, OptionsAreChecked) {
  EXPECT_NO_THROW(check_weight_options({0, 1}));
  EXPECT_NO_THROW(check_weight_options({4, 2}));
  EXPECT_THROW(check_weight_options({-1, 1}), InputError);
  EXPECT_THROW(check_weight_options({5, 1}), InputError);
  EXPECT_THROW(check_weight_options({1, 0}), InputError);
  EXPECT_THROW(check_weight_options({1, 3}), InputError);
  EXPECT_THROW((WeightFunctions(mesh_of(kFamilies[5]), WeightFunctionOptions{1, 3})), InputError);
}

TEST(WeightFunctions, ZeroOnTheDirichletPartPositiveAtOwnVertexAndNeumannPart) {
  for (const Family& f : kFamilies) {
    const PolygonMesh& mesh = mesh_of(f);
    for (const WeightFunctionOptions& o : kOptionSets) {
      const WeightFunctions wf(mesh, o);
      const int N = o.degree * wf.lattice_size();
      int failures = 0;
      for (int c = 0; c < mesh.num_cells() && failures < 10; ++c) {
        const int n = mesh.cell_size(c);
        const FanLattice lat = wf.lattice(c);
        ASSERT_EQ(lat.divisions(), N);
        for (int k = 0; k < n; ++k) {
          const auto v = wf.values(c, k);
          ASSERT_EQ(static_cast<int>(v.size()), lat.node_count());
          const double scale = weight_scale(mesh, c);
          // Own vertex.
          if (!(v[1 + k] > 1e-6 * scale)) {
            ++failures;
            ADD_FAILURE() << label(f, o) << ": cell " << c << " vertex " << k
                          << ": w at its own vertex = " << v[1 + k];
          }
          // Other vertices: exactly zero.
          for (int j = 0; j < n; ++j)
            if (j != k && v[1 + j] != 0.0) {
              ++failures;
              ADD_FAILURE() << label(f, o) << ": cell " << c << " w_" << k << " at vertex " << j
                            << " = " << v[1 + j] << ", expected exactly 0";
            }
          // Edge nodes of edges not touching k: exactly zero. Edges touching k: zero only if
          // interior to the patch is impossible (they are interior or Neumann): positive.
          for (int e = 0; e < n; ++e) {
            const bool touches = e == k || e == (k + n - 1) % n;
            for (int t = 1; t < N; ++t) {
              const double value = v[lat.edge_node(e, t)];
              if (!touches && value != 0.0) {
                ++failures;
                ADD_FAILURE() << label(f, o) << ": cell " << c << " w_" << k << " on edge " << e
                              << " node " << t << " = " << value << ", expected exactly 0";
              }
              if (touches && !(value > 0.0)) {
                ++failures;
                ADD_FAILURE() << label(f, o) << ": cell " << c << " w_" << k
                              << " on its incident edge " << e << " node " << t << " = " << value
                              << ", expected > 0"
                              << (mesh.neighbor(c, e) < 0 ? " (Neumann boundary edge)" : "");
              }
            }
          }
        }
      }
    }
  }
}

TEST(WeightFunctions, PositiveAtEveryQuadraturePoint) {
  for (const Family& f : kFamilies) {
    const PolygonMesh& mesh = mesh_of(f);
    for (const WeightFunctionOptions& o : kOptionSets) {
      const WeightFunctions wf(mesh, o);
      double worst = INFINITY;  // smallest w / cell area seen
      int failures = 0;
      std::set<int> bad_cells;
      for (int points : {1, 3, 6}) {
        const TriangleRule& rule = triangle_rule(points);
        for (int c = 0; c < mesh.num_cells(); ++c) {
          const int n = mesh.cell_size(c);
          std::vector<double> w(n);
          std::vector<Eigen::Vector2d> g(n);
          for (int fan = 0; fan < n; ++fan)
            for (int q = 0; q < rule.size(); ++q) {
              wf.evaluate(c, fan, rule.bary[q], w.data(), g.data());
              for (int k = 0; k < n; ++k) {
                worst = std::min(worst, w[k] / weight_scale(mesh, c));
                if (!(w[k] > 0.0)) bad_cells.insert(c);
                if (!(w[k] > 0.0) && failures++ < 5)
                  ADD_FAILURE() << label(f, o) << ": " << points << "-point rule, cell " << c
                                << " (largest interior angle " << largest_angle_degrees(mesh, c)
                                << " deg) fan " << fan << " point " << q << ": w_" << k << " = "
                                << w[k];
              }
            }
        }
      }
      std::ostringstream cells;
      for (int c : bad_cells) cells << ' ' << c;
      EXPECT_EQ(failures, 0) << label(f, o)
                             << ": cells with w <= 0 at a quadrature point:" << cells.str();
      std::cout << "[ weights ] " << label(f, o)
                << ": min w / cell area at quadrature points = " << worst << "\n";
    }
  }
}

TEST(WeightFunctions, PatchProblemIsConformingAcrossCells) {
  for (const Family& f : kFamilies) {
    const PolygonMesh& mesh = mesh_of(f);
    for (const WeightFunctionOptions& o :
         {WeightFunctionOptions{1, 1}, WeightFunctionOptions{1, 2}}) {
      const WeightFunctions wf(mesh, o);
      const int N = o.degree * wf.lattice_size();
      // Same value of w_v at v in every cell of its patch.
      for (int v = 0; v < mesh.num_vertices(); ++v) {
        double ref = NAN;
        for (int c : mesh.vertex_cells(v)) {
          const auto loop = mesh.cell_vertices(c);
          const int k = static_cast<int>(std::find(loop.begin(), loop.end(), v) - loop.begin());
          const double value = wf.values(c, k)[1 + k];
          if (std::isnan(ref)) ref = value;
          EXPECT_NEAR(value, ref, 1e-14 * std::abs(ref)) << label(f, o) << " vertex " << v;
        }
      }
      // Same values along every interior edge, for both end vertices' weight functions.
      for (const MeshEdge& e : mesh.edges()) {
        if (e.on_boundary()) continue;
        const auto l0 = mesh.cell_vertices(e.cell0), l1 = mesh.cell_vertices(e.cell1);
        const int n0 = static_cast<int>(l0.size()), n1 = static_cast<int>(l1.size());
        const int k0 = static_cast<int>(std::find(l0.begin(), l0.end(), e.v0) - l0.begin());
        const int k1 = static_cast<int>(std::find(l1.begin(), l1.end(), e.v1) - l1.begin());
        ASSERT_EQ(l0[(k0 + 1) % n0], e.v1);
        ASSERT_EQ(l1[(k1 + 1) % n1], e.v0);
        const FanLattice lat0 = wf.lattice(e.cell0), lat1 = wf.lattice(e.cell1);
        for (int end = 0; end < 2; ++end) {
          const int j0 = end == 0 ? k0 : (k0 + 1) % n0;  // local index of the end in cell0
          const int j1 = end == 0 ? (k1 + 1) % n1 : k1;  // ... and in cell1
          const auto w0 = wf.values(e.cell0, j0), w1 = wf.values(e.cell1, j1);
          for (int t = 1; t < N; ++t)
            EXPECT_EQ(w0[lat0.edge_node(k0, t)], w1[lat1.edge_node(k1, N - t)])
                << label(f, o) << ": edge " << e.v0 << "-" << e.v1 << " node " << t;
        }
      }
    }
  }
}

TEST(WeightFunctions, EvaluateInterpolatesNodalValuesAndGradientMatchesDifferences) {
  for (const Family& f : kFamilies) {
    const PolygonMesh& mesh = mesh_of(f);
    for (const WeightFunctionOptions& o : kOptionSets) {
      const WeightFunctions wf(mesh, o);
      const int N = o.degree * wf.lattice_size();
      const int m = wf.lattice_size();
      for (int c = 0; c < mesh.num_cells(); c += 7) {
        const int n = mesh.cell_size(c);
        const FanLattice lat = wf.lattice(c);
        const auto loop = mesh.cell_vertices(c);
        const double scale = weight_scale(mesh, c);
        std::vector<double> w(n), wp(n), wm(n);
        std::vector<Eigen::Vector2d> g(n), gd(n);
        for (int fan = 0; fan < n; ++fan) {
          // At every lattice node of the fan triangle, evaluate() returns the nodal value.
          for (int i = 0; i <= N; ++i)
            for (int j = 0; i + j <= N; ++j) {
              const Eigen::Vector3d bary(1.0 - double(i + j) / N, double(i) / N, double(j) / N);
              wf.evaluate(c, fan, bary, w.data(), g.data());
              for (int k = 0; k < n; ++k)
                EXPECT_NEAR(w[k], wf.values(c, k)[lat.node(fan, i, j)], 1e-12 * scale)
                    << label(f, o) << " cell " << c << " fan " << fan << " (" << i << "," << j
                    << ") w_" << k;
            }
          // At the centre of every sub-triangle, the gradient matches central differences along
          // the two fan directions (exact for P1 and P2 up to round-off).
          const Point C = wf.centroids()[c];
          const Point A = mesh.vertex(loop[fan]), B = mesh.vertex(loop[(fan + 1) % n]);
          for (int a = 0; a < m; ++a)
            for (int b = 0; a + b < m; ++b)
              for (bool up : {true, false}) {
                if (!up && a + b > m - 2) continue;
                const double u = up ? a + 1.0 / 3 : a + 2.0 / 3, v = up ? b + 1.0 / 3 : b + 2.0 / 3;
                const Eigen::Vector3d bary(1.0 - (u + v) / m, u / m, v / m);
                wf.evaluate(c, fan, bary, w.data(), g.data());
                const double d = 1e-3 / m;
                for (int dir = 0; dir < 2; ++dir) {
                  Eigen::Vector3d step = Eigen::Vector3d::Zero();
                  step[0] = -d;
                  step[1 + dir] = d;
                  wf.evaluate(c, fan, bary + step, wp.data(), gd.data());
                  wf.evaluate(c, fan, bary - step, wm.data(), gd.data());
                  const Eigen::Vector2d dx = d * ((dir == 0 ? A : B) - C);
                  for (int k = 0; k < n; ++k) {
                    const double fd = (wp[k] - wm[k]) / 2.0;
                    EXPECT_NEAR(g[k].dot(dx), fd, 1e-9 * scale)
                        << label(f, o) << " cell " << c << " fan " << fan << " sub (" << a << ","
                        << b << "," << up << ") w_" << k << " direction " << dir;
                  }
                }
              }
        }
      }
    }
  }
}

TEST(WeightFunctions, ThreadCountDoesNotChangeTheResult) {
  // Refinement 2 with P2 makes patches large enough for the sparse solver; P1 refinement 1
  // exercises the dense one.
  for (const Family& f : kFamilies) {
    const PolygonMesh& mesh = mesh_of(f);
    for (const WeightFunctionOptions& o :
         {WeightFunctionOptions{1, 1}, WeightFunctionOptions{2, 2}}) {
      const WeightFunctions one(mesh, o, 1), two(mesh, o, 2);
      for (int c = 0; c < mesh.num_cells(); ++c) {
        EXPECT_EQ(one.centroids()[c], two.centroids()[c]);
        for (int k = 0; k < mesh.cell_size(c); ++k) {
          const auto a = one.values(c, k), b = two.values(c, k);
          ASSERT_EQ(a.size(), b.size());
          for (std::size_t i = 0; i < a.size(); ++i)
            ASSERT_EQ(a[i], b[i]) << label(f, o) << " cell " << c << " vertex " << k << " node "
                                  << i;
        }
      }
    }
  }
}

TEST(WeightFunctions, CondensedCellsGiveThePatchSolution) {
  // Eliminating each cell's inner nodes first is the same linear algebra in another order.
  for (const Family& f : kFamilies) {
    const PolygonMesh& mesh = mesh_of(f);
    for (const WeightFunctionOptions& o :
         {WeightFunctionOptions{0, 1}, WeightFunctionOptions{1, 1}, WeightFunctionOptions{0, 2},
          WeightFunctionOptions{1, 2}}) {
      WeightFunctionOptions per_patch = o;
      per_patch.condense = false;
      const WeightFunctions condensed(mesh, o), patches(mesh, per_patch);
      double worst = 0.0;
      for (int c = 0; c < mesh.num_cells(); ++c)
        for (int k = 0; k < mesh.cell_size(c); ++k) {
          const auto a = condensed.values(c, k), b = patches.values(c, k);
          ASSERT_EQ(a.size(), b.size());
          for (std::size_t i = 0; i < a.size(); ++i)
            worst = std::max(worst, std::abs(a[i] - b[i]) / weight_scale(mesh, c));
        }
      EXPECT_LT(worst, 1e-12) << label(f, o);
      std::cout << label(f, o) << ": largest difference " << worst << " of the cell's area\n";
    }
  }
}

TEST(WeightFunctions, RefinementConvergesTowardsTheContinuousSolution) {
  // The value of w_k at its own vertex is a functional of the patch solution; with h-refinement
  // of the lattice it should settle (successive differences shrink). Printed for the record.
  const PolygonMesh& mesh = mesh_of(kFamilies[0]);
  const int cell = mesh.num_cells() / 2;
  double previous = NAN, previous_change = NAN;
  for (int r = 0; r <= 3; ++r) {
    const WeightFunctions wf(mesh, {r, 2});
    const double value = wf.values(cell, 0)[1];
    if (!std::isnan(previous)) {
      const double change = std::abs(value - previous);
      std::cout << "[ weights ] rcp cell " << cell << " P2 refinement " << r
                << ": w_0(v_0) = " << value << " change " << change << "\n";
      if (!std::isnan(previous_change)) {
        EXPECT_LT(change, previous_change);
      }
      previous_change = change;
    }
    previous = value;
  }
}

}  // namespace
}  // namespace vorodg
