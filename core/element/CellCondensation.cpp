#include "core/element/CellCondensation.hpp"

#include <algorithm>
#include <string>

#include "core/element/LatticeStiffness.hpp"
#include "core/element/SmallCholesky.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {

void condense_cell(const PolygonMesh& mesh, const Point& centroid, int cell, int N, int m,
                   int degree, CellCondensation& cc) {
  const int n = mesh.cell_size(cell);
  const FanLattice lattice(n, N);
  cc.n = n;
  cc.N = N;
  cc.nodes = lattice.node_count();
  const int nn = cc.nodes;
  std::fill(cc.K.begin(), cc.K.begin() + nn * nn, 0.0);
  std::fill(cc.f.begin(), cc.f.begin() + nn, 0.0);
  for_each_sub_triangle(mesh, centroid, cell, N, m, degree,
                        [&](const SubTriangleNodes& sub, const SubTriangleMatrices& local) {
                          for (int i = 0; i < sub.count; ++i) {
                            cc.f[sub.node[i]] += local.f[i];
                            for (int j = 0; j < sub.count; ++j)
                              cc.K[sub.node[i] * nn + sub.node[j]] += local.K(i, j);
                          }
                        });
  const int first_edge_node = 1 + n + n * (N - 1);
  cc.n_inner = 0;
  for (int node = 0; node < nn; ++node)
    if (node == 0 || (node > n && node < first_edge_node) || node >= lattice.first_interior())
      cc.inner[cc.n_inner++] = node;
  const int ni = cc.n_inner;
  for (int i = 0; i < ni; ++i)
    for (int j = 0; j <= i; ++j) cc.L[i * ni + j] = cc.K[cc.inner[i] * nn + cc.inner[j]];
  if (!cholesky_in_place(cc.L.data(), ni))
    throw NumericalError("cell " + std::to_string(cell) +
                         ": its weight-function lattice matrix is not positive definite (a "
                         "degenerate fan triangle)");
}

void vertex_blocks(const CellCondensation& cc, double* out) {
  const int ni = cc.n_inner, nn = cc.nodes, nb = 2 * cc.N - 1;
  const FanLattice lattice(cc.n, cc.N);
  double y_f[kMaxCondensedNodes], y[2 * kMaxCondensedNodes][kMaxCondensedNodes];
  for (int i = 0; i < ni; ++i) y_f[i] = cc.f[cc.inner[i]];
  forward_solve(cc.L.data(), ni, y_f);
  for (int k = 0; k < cc.n; ++k, out += nb * nb + nb) {
    int bn[2 * kMaxCondensedNodes];
    CellCondensation::boundary_nodes(lattice, cc.n, cc.N, k, bn);
    for (int a = 0; a < nb; ++a) {
      for (int i = 0; i < ni; ++i) y[a][i] = cc.K[cc.inner[i] * nn + bn[a]];
      forward_solve(cc.L.data(), ni, y[a]);
    }
    for (int a = 0; a < nb; ++a) {
      for (int b = 0; b < nb; ++b) {
        double v = cc.K[bn[a] * nn + bn[b]];
        for (int i = 0; i < ni; ++i) v -= y[a][i] * y[b][i];
        out[a * nb + b] = v;
      }
      double g = cc.f[bn[a]];
      for (int i = 0; i < ni; ++i) g -= y[a][i] * y_f[i];
      out[nb * nb + a] = g;
    }
  }
}

void recover_inner_values(const CellCondensation& cc, int N, double* values) {
  const int nn = cc.nodes, ni = cc.n_inner, nb = 2 * N - 1;
  const FanLattice lat(cc.n, N);
  for (int k = 0; k < cc.n; ++k) {
    double* out = values + static_cast<std::size_t>(k) * nn;
    int bn[2 * kMaxCondensedNodes];
    CellCondensation::boundary_nodes(lat, cc.n, N, k, bn);
    double x[kMaxCondensedNodes];
    for (int i = 0; i < ni; ++i) {
      double r = cc.f[cc.inner[i]];
      for (int a = 0; a < nb; ++a) r -= cc.K[cc.inner[i] * nn + bn[a]] * out[bn[a]];
      x[i] = r;
    }
    forward_solve(cc.L.data(), ni, x);
    backward_solve(cc.L.data(), ni, x);
    for (int i = 0; i < ni; ++i) out[cc.inner[i]] = x[i];
  }
}

}  // namespace vorodg
