#pragma once
// Linear (P1) and quadratic (P2) Lagrange bases on the sub-triangles of a FanLattice: the
// finite-element space of the weight functions. A P2 function on an m-lattice uses the nodes of
// the 2m-lattice (corners and edge midpoints of every sub-triangle).
#include <Eigen/Core>
#include <Eigen/LU>
#include <array>

#include "core/element/FanLattice.hpp"

namespace vorodg {

/// Nodes of one sub-triangle, in the order corner0, corner1, corner2 (then, for P2, midpoints
/// 01, 12, 20), as cell-local node indices.
struct SubTriangleNodes {
  std::array<int, 6> node{};
  int count = 3;
};

/// Sub-triangle (a, b, up) of fan k in an m-lattice; `lattice` has m (P1) or 2m (P2) divisions.
inline SubTriangleNodes sub_triangle_nodes(const FanLattice& lattice, int k, int a, int b, bool up,
                                           int degree) {
  const int s = degree;  // lattice steps per sub-triangle side
  std::array<int, 3> ci, cj;
  if (up) {
    ci = {a, a + 1, a};
    cj = {b, b, b + 1};
  } else {
    ci = {a + 1, a, a + 1};
    cj = {b + 1, b + 1, b};
  }
  SubTriangleNodes out;
  for (int c = 0; c < 3; ++c) out.node[c] = lattice.node(k, s * ci[c], s * cj[c]);
  if (degree == 2) {
    out.count = 6;
    for (int e = 0; e < 3; ++e) {
      const int p = e, q = (e + 1) % 3;
      out.node[3 + e] = lattice.node(k, ci[p] + ci[q], cj[p] + cj[q]);
    }
  }
  return out;
}

/// Basis values and (xi, eta)-derivatives at local point (xi, eta) of a sub-triangle.
inline void lattice_basis(int degree, double xi, double eta, double* phi, double (*dphi)[2]) {
  const double l0 = 1.0 - xi - eta, l1 = xi, l2 = eta;
  if (degree == 1) {
    phi[0] = l0, phi[1] = l1, phi[2] = l2;
    dphi[0][0] = -1, dphi[0][1] = -1;
    dphi[1][0] = 1, dphi[1][1] = 0;
    dphi[2][0] = 0, dphi[2][1] = 1;
    return;
  }
  // dl/dxi = (-1, 1, 0), dl/deta = (-1, 0, 1)
  const double l[3] = {l0, l1, l2};
  const double dl[3][2] = {{-1, -1}, {1, 0}, {0, 1}};
  for (int c = 0; c < 3; ++c) {
    phi[c] = l[c] * (2 * l[c] - 1);
    for (int d = 0; d < 2; ++d) dphi[c][d] = (4 * l[c] - 1) * dl[c][d];
  }
  for (int e = 0; e < 3; ++e) {
    const int p = e, q = (e + 1) % 3;
    phi[3 + e] = 4 * l[p] * l[q];
    for (int d = 0; d < 2; ++d) dphi[3 + e][d] = 4 * (dl[p][d] * l[q] + l[p] * dl[q][d]);
  }
}

/// Jacobian d x / d (xi, eta) of a sub-triangle of fan triangle (C, A, B) in an m-lattice.
inline Eigen::Matrix2d sub_triangle_jacobian(const Eigen::Vector2d& C, const Eigen::Vector2d& A,
                                             const Eigen::Vector2d& B, int m, bool up) {
  Eigen::Matrix2d J;
  J.col(0) = (A - C) / m;
  J.col(1) = (B - C) / m;
  return up ? J : Eigen::Matrix2d(-J);
}

}  // namespace vorodg
