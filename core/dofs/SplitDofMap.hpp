#pragma once
// Which (cell, vertex) pairs share their displacement DOFs (report section 4): the pairs of two
// cells on an edge are joined at both end vertices when the edge is connected, and the nodes are
// the equivalence classes of that relation (union-find). All interior edges connected gives the
// continuous space (one node per vertex); none gives the fully discontinuous one (one node per
// cell corner). A fracture scene connects every edge where no crack may form, so the unknowns
// split only where the scene needs them to. Nodes are numbered in order of their first pair
// (cell by cell, vertex by vertex), so the numbering depends only on the mesh and the edge set.
#include <span>
#include <vector>

#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

class SplitDofMap {
 public:
  /// `connected[e]` (one entry per mesh edge; boundary entries are ignored) joins the two cells'
  /// copies of edge e's end vertices.
  SplitDofMap(const PolygonMesh& mesh, const std::vector<char>& connected);
  /// Every interior edge connected (CG) or none (full DG).
  static SplitDofMap continuous(const PolygonMesh& mesh);
  static SplitDofMap discontinuous(const PolygonMesh& mesh);

  int num_nodes() const { return num_nodes_; }
  int num_dofs() const { return 2 * num_nodes_; }
  /// The node of cell c's vertex k (k in the cell's loop order).
  int node(int c, int k) const { return node_[offsets_[c] + k]; }
  /// The nodes at mesh vertex v (one per class of its cells' copies).
  std::span<const int> vertex_nodes(int v) const {
    return {vertex_nodes_.data() + vertex_offsets_[v],
            vertex_nodes_.data() + vertex_offsets_[v + 1]};
  }
  /// Whether interior edge e joins its cells: both end vertices share their nodes.
  bool joins(const PolygonMesh& mesh, int e) const;

 private:
  std::vector<int> offsets_;  // the mesh's cell offsets
  std::vector<int> node_;     // per (cell, vertex) pair, CSR like the cells' loops
  std::vector<int> vertex_offsets_, vertex_nodes_;
  int num_nodes_ = 0;
};

}  // namespace vorodg
