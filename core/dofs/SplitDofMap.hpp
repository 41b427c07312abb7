#pragma once
// Which (cell, vertex) pairs share their displacement DOFs (report section 4): the pairs of two
// cells on an edge are joined at both end vertices when the edge is connected, and the nodes are
// the equivalence classes of that relation (union-find). All interior edges connected gives the
// continuous space (one node per vertex); none gives the fully discontinuous one (one node per
// cell corner). A fracture scene connects every edge where no crack may form, so the unknowns
// split only where the scene needs them to. Nodes are numbered in order of their first pair
// (cell by cell, vertex by vertex), so the numbering depends only on the mesh and the edge set.
//
// A class only ever holds pairs at one mesh vertex, so when edges are disconnected only the
// classes at their end vertices change. `disconnect` re-classes those alone and renumbers in
// one pass over the pairs; the result is the map the constructor would build from the new edge
// set, node for node.
#include <span>
#include <vector>

#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

class SplitDofMap {
 public:
  /// `connected[e]` (one entry per mesh edge; boundary entries are ignored) joins the two cells'
  /// copies of edge e's end vertices.
  SplitDofMap(const PolygonMesh& mesh, const std::vector<char>& connected);
  /// The same map after `edges` were disconnected: `connected` is the new edge set (those
  /// edges off, every other flag as before). Throws InputError for an edge out of range.
  void disconnect(const PolygonMesh& mesh, const std::vector<char>& connected,
                  std::span<const int> edges);
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
  /// Numbers the classes in order of their smallest pair (first_) and lists each vertex's nodes.
  void number(const PolygonMesh& mesh);
  /// Re-classes the pairs at vertex v under the edge set `connected` (sets their first_).
  void reclass(const PolygonMesh& mesh, const std::vector<char>& connected, int v);

  std::vector<int> offsets_;  // the mesh's cell offsets
  std::vector<int> first_;    // per pair, the smallest pair of its class
  std::vector<int> node_;     // per (cell, vertex) pair, CSR like the cells' loops
  std::vector<int> vertex_offsets_, vertex_nodes_;
  int num_nodes_ = 0;
};

}  // namespace vorodg
