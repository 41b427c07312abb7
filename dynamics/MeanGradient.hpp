#pragma once
// The mean gradient of a field over a polygon cell, from its vertex values alone:
//     G = (1/A) int_cell grad w dA = (1/A) int_boundary w (x) n ds = sum_k w_k (x) b_k,
//     b_k = (nL_{k-1} + nL_k) / (2 A),   nL_e = (dy, -dx) of edge e,
// exact for any field linear along each edge (the trapezoid rule on each edge). Two users share
// it, so that they measure the same thing: CorotationalFrames takes a cell's turn from the mean
// deformation gradient, and BulkViscosity its volumetric strain rate from the mean velocity
// gradient, tr G = sum_k b_k . v_k. Since sum_k b_k = 0, a uniform field has a zero gradient,
// and A sum_k b_k . v_k is the exact virtual work of a uniform pressure on the cell, which is
// why BulkViscosity's nodal force is -q A b_k.
#include <Eigen/Core>
#include <vector>

#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

class MeanGradient {
 public:
  /// Throws InputError naming the cell if a cell has no area.
  explicit MeanGradient(const PolygonMesh& mesh);

  int num_cells() const { return static_cast<int>(offsets_.size()) - 1; }
  int cell_size(int c) const { return offsets_[c + 1] - offsets_[c]; }
  /// Cell c's weights b_k, (x, y) for each of its vertices k in order.
  const double* weights(int c) const { return b_.data() + 2 * std::size_t(offsets_[c]); }
  /// Cell c's area (> 0 whatever its orientation).
  double area(int c) const { return area_[c]; }
  /// G = sum_k w_k (x) b_k of cell c from vertex values w[2k], w[2k + 1] (absolute or relative
  /// to vertex 0: the same, since sum_k b_k = 0). Inline: every cell calls it every step.
  Eigen::Matrix2d gradient(int c, const double* w) const { return gradient(c, cell_size(c), w); }
  /// The same for a caller that knows the cell's size n (a compile-time constant in the
  /// force's fixed-size loops, which the compiler then unrolls).
  Eigen::Matrix2d gradient(int c, int n, const double* w) const {
    const double* b = weights(c);
    Eigen::Matrix2d g = Eigen::Matrix2d::Zero();
    for (int k = 0; k < n; ++k) {
      g(0, 0) += w[2 * k] * b[2 * k], g(0, 1) += w[2 * k] * b[2 * k + 1];
      g(1, 0) += w[2 * k + 1] * b[2 * k], g(1, 1) += w[2 * k + 1] * b[2 * k + 1];
    }
    return g;
  }
  /// G of cell c's field read straight from node values (field[2 node[k]], field[2 node[k] + 1]
  /// for its vertex k), relative to vertex 0: a field uniform over the cell has exactly G = 0.
  Eigen::Matrix2d gradient_at_nodes(int c, const int* node, const double* field) const {
    const int n = cell_size(c);
    const double* b = weights(c);
    const double x0 = field[2 * node[0]], y0 = field[2 * node[0] + 1];
    Eigen::Matrix2d g = Eigen::Matrix2d::Zero();
    for (int k = 0; k < n; ++k) {
      const double x = field[2 * node[k]] - x0, y = field[2 * node[k] + 1] - y0;
      g(0, 0) += x * b[2 * k], g(0, 1) += x * b[2 * k + 1];
      g(1, 0) += y * b[2 * k], g(1, 1) += y * b[2 * k + 1];
    }
    return g;
  }
  /// tr G, the mean divergence of cell c's field w.
  double divergence(int c, const double* w) const;

 private:
  std::vector<int> offsets_;
  std::vector<double> b_;     // per pair: b_k (x, y)
  std::vector<double> area_;  // per cell
};

}  // namespace vorodg
