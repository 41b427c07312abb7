#pragma once
// The sub-triangulation of a cell on which its nodes' weight functions are finite-element
// functions: the fan from the centroid, each fan triangle (C, v_k, v_k+1) cut into a regular
// lattice of N x N divisions. Lattice point (i, j) of fan k sits at
//   C + (i/N) (v_k - C) + (j/N) (v_k+1 - C),   i, j >= 0, i + j <= N.
// Cell-local node numbering (shared by every node's weight function on the cell):
//   0                      the centroid
//   1 .. n                 the cell's vertices
//   then n spokes (C -> v_k) with N-1 interior nodes each, from the centroid outwards,
//   then n edges (v_k -> v_k+1) with N-1 interior nodes each, from v_k,
//   then n fan interiors with (N-1)(N-2)/2 nodes each.
#include <Eigen/Core>
#include <algorithm>

namespace vorodg {

class FanLattice {
 public:
  FanLattice(int n_vertices, int divisions) : n_(n_vertices), N_(divisions) {}

  int divisions() const { return N_; }
  int node_count() const { return 1 + n_ + 2 * n_ * (N_ - 1) + n_ * interior_per_fan(); }

  /// Cell-local node index of lattice point (i, j) of fan k.
  int node(int k, int i, int j) const {
    const int k1 = (k + 1) % n_;
    if (i == 0 && j == 0) return 0;
    if (i == N_) return 1 + k;
    if (j == N_) return 1 + k1;
    if (i + j == N_) return edge_node(k, j);
    if (j == 0) return spoke_node(k, i);
    if (i == 0) return spoke_node(k1, j);
    // interior: rows j = 1..N-2, in row j the points i = 1..N-1-j
    const int before = (j - 1) * (N_ - 1) - (j - 1) * j / 2;
    return first_interior() + k * interior_per_fan() + before + (i - 1);
  }
  /// Node t (1..N-1) of spoke k, counted from the centroid.
  int spoke_node(int k, int t) const { return 1 + n_ + k * (N_ - 1) + (t - 1); }
  /// Node t (1..N-1) of edge k (v_k -> v_k+1), counted from v_k.
  int edge_node(int k, int t) const { return 1 + n_ + n_ * (N_ - 1) + k * (N_ - 1) + (t - 1); }
  bool is_vertex(int node) const { return node >= 1 && node <= n_; }
  /// First node inside the fan triangles (after the centroid, vertices, spokes and edges).
  int first_interior() const { return 1 + n_ + 2 * n_ * (N_ - 1); }
  /// The edge (k) whose interior holds `node`, or -1.
  int edge_of(int node) const {
    const int first = 1 + n_ + n_ * (N_ - 1);
    return (node >= first && node < first + n_ * (N_ - 1)) ? (node - first) / (N_ - 1) : -1;
  }

 private:
  int interior_per_fan() const { return (N_ - 1) * (N_ - 2) / 2; }
  int n_, N_;
};

/// Where a point of fan triangle k falls in the lattice: the sub-triangle and the local
/// coordinates (xi, eta) in it. Sub-triangles of an m-lattice are "up" (corners (a,b), (a+1,b),
/// (a,b+1)) or "down" (corners (a+1,b+1), (a,b+1), (a+1,b)), with (xi, eta) measured from the
/// first corner towards the second and third.
struct LatticeLocation {
  int a = 0, b = 0;
  bool up = true;
  double xi = 0.0, eta = 0.0;
};

/// Locates barycentric point (l_c, l_a, l_b) of a fan triangle in an m-lattice.
inline LatticeLocation locate_in_lattice(const Eigen::Vector3d& bary, int m) {
  const double u = m * bary[1], v = m * bary[2];
  LatticeLocation loc;
  loc.a = std::min(static_cast<int>(u), m - 1);
  loc.b = std::min(static_cast<int>(v), m - 1 - loc.a);
  const double fu = u - loc.a, fv = v - loc.b;
  loc.up = fu + fv <= 1.0 || loc.a + loc.b == m - 1;
  if (loc.up) {
    loc.xi = fu;
    loc.eta = fv;
  } else {
    loc.xi = 1.0 - fu;   // towards (a, b+1)
    loc.eta = 1.0 - fv;  // towards (a+1, b)
  }
  return loc;
}

}  // namespace vorodg
