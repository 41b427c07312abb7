#pragma once
// The stiffness and load of the weight functions' lattice problem, -lap w = 1 on a cell's fan
// lattice (WeightFunctions): per sub-triangle from reference integrals and its metric, and the
// loop over a cell's sub-triangles that both the per-vertex patch solve and the cell condensation
// assemble from.
#include <Eigen/Core>

#include "core/element/FanLattice.hpp"
#include "core/element/LatticeBasis.hpp"
#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

/// Stiffness and load of one sub-triangle of fan triangle (C, A, B): every sub-triangle of the
/// lattice, up or down, has the same matrices in its local node order (the down triangles are
/// the up ones turned by 180 degrees).
struct SubTriangleMatrices {
  Eigen::Matrix<double, 6, 6> K;
  Eigen::Matrix<double, 6, 1> f;
};

/// The matrices of one sub-triangle of fan triangle (C, A, B) with m sub-triangles per side, for
/// P1 or P2 (`degree`).
SubTriangleMatrices sub_triangle_matrices(const Point& C, const Point& A, const Point& B, int m,
                                          int degree);

/// Calls add(nodes, matrices) for every sub-triangle of the cell's lattice (N divisions per fan
/// triangle side, m sub-triangles), with its cell-local nodes and its stiffness and load.
template <class Add>
void for_each_sub_triangle(const PolygonMesh& mesh, const Point& centroid, int cell, int N, int m,
                           int degree, Add&& add) {
  const auto loop = mesh.cell_vertices(cell);
  const int n = static_cast<int>(loop.size());
  const FanLattice lattice(n, N);
  for (int k = 0; k < n; ++k) {
    const auto local = sub_triangle_matrices(centroid, mesh.vertex(loop[k]),
                                             mesh.vertex(loop[(k + 1) % n]), m, degree);
    for (int a = 0; a < m; ++a)
      for (int b = 0; a + b < m; ++b)
        for (bool up : {true, false}) {
          if (!up && a + b > m - 2) continue;
          add(sub_triangle_nodes(lattice, k, a, b, up, degree), local);
        }
  }
}

}  // namespace vorodg
