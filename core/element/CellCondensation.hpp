#pragma once
// The static condensation of one cell's weight-function lattice problem (WeightFunctions'
// default path): the inner nodes eliminated once per cell, Schur blocks per vertex for the
// patch problems, and the inner values recovered from the boundary values.
#include <array>

#include "core/element/FanLattice.hpp"
#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

/// Lattices up to this many nodes per cell are solved by condensing each cell onto its boundary
/// (the default, P2 unrefined, has 3n + 1); finer ones by one sparse or dense solve per patch.
inline constexpr int kMaxCondensedNodes = 64;

/// One cell's weight-function problem, -lap w = 1 on its lattice, split into the nodes inside
/// the cell (centroid, spokes, fan interiors: `inner`) and those on its boundary (vertices and
/// edge nodes). Every weight function of a vertex is, inside each cell of its patch, the solution
/// of this problem for its boundary values, so the inner nodes are eliminated cell by cell, once
/// for all the cell's vertices, and the patch problems keep only the vertex and the nodes of the
/// edges at it.
struct CellCondensation {
  int n = 0, N = 0, nodes = 0, n_inner = 0;
  std::array<int, kMaxCondensedNodes> inner{};                      // inner nodes, in node order
  std::array<double, kMaxCondensedNodes * kMaxCondensedNodes> K{};  // full, row-major
  std::array<double, kMaxCondensedNodes> f{};
  std::array<double, kMaxCondensedNodes * kMaxCondensedNodes> L{};  // factor of K(inner, inner)

  /// The nodes whose values a vertex's weight function may have nonzero on the cell's boundary:
  /// vertex k, then the nodes of edge k and of edge k-1, each by distance from vertex k.
  static void boundary_nodes(const FanLattice& lattice, int n, int N, int k, int* out) {
    out[0] = 1 + k;
    for (int s = 1; s < N; ++s) {
      out[s] = lattice.edge_node(k, s);
      out[N - 1 + s] = lattice.edge_node((k + n - 1) % n, N - s);
    }
  }
};

/// Stiffness and load of the cell's lattice, and the factor of its inner block. Throws
/// NumericalError naming the cell if that block is not positive definite.
void condense_cell(const PolygonMesh& mesh, const Point& centroid, int cell, int N, int m,
                   int degree, CellCondensation& cc);

/// Per vertex k of the condensed cell: the Schur complement of the inner nodes on the vertex's
/// 2N - 1 boundary nodes (row-major) and its load, `block` entries then `2N - 1`.
void vertex_blocks(const CellCondensation& cc, double* out);

/// The inner-node values of each of the cell's vertices' weight functions (`values`: the cell's
/// block, vertex after vertex), from their boundary values already there, by the condensed
/// cell's factor of K(inner, inner).
void recover_inner_values(const CellCondensation& cc, int N, double* values);

}  // namespace vorodg
