#pragma once
// A nested-dissection ordering from the nodes' positions instead of a graph partitioner.
//
// A mesh's node graph is planar and its nodes have coordinates, so a straight cut through the
// median of the longer side of a part's bounding box splits it into halves whose boundary, the
// nodes adjacent to the other half, is a separator of O(sqrt n) nodes (Lipton-Tarjan's bound, met
// by a line on a quasi-uniform mesh). Ordering the halves first, each dissected again, and the
// separator last gives the fill of nested dissection (O(n log n) in 2D) at the cost of a few
// partial sorts, where METIS's multilevel bisection costs several times the minimum-degree
// ordering it beats (docs/performance.md, "The geometric dissection").
#include <Eigen/Core>
#include <vector>

namespace vorodg {

/// The adjacency of a symmetric graph in compressed columns (both triangles, no diagonal).
struct Adjacency {
  std::vector<int> col_start, rows;
};

/// The symmetric adjacency of a graph given by its lower triangle (compressed columns; the
/// diagonal, if present, is dropped).
Adjacency symmetric_adjacency(const std::vector<int>& lower_col_start,
                              const std::vector<int>& lower_rows);

/// A fill-reducing permutation (perm[k] = the node eliminated k-th, CHOLMOD's convention) by
/// recursive coordinate bisection. A part of at most `leaf_size` nodes is ordered as it comes; a
/// larger one is split at the median of its longer extent, and the separator, a minimum vertex
/// cover of the edges between the halves, is ordered after both. points: one column per node.
/// Throws InputError if the sizes disagree or a coordinate is not finite.
std::vector<int> geometric_dissection(const Adjacency& graph, const Eigen::Matrix2Xd& points,
                                      int leaf_size = 8);

}  // namespace vorodg
