#pragma once
// Which (cell, vertex) pairs share their displacement DOFs (report section 4): the pairs of two
// cells on an edge are joined at both end vertices when the edge is connected, and the nodes are
// the equivalence classes of that relation (union-find). All interior edges connected gives the
// continuous space (one node per vertex); none gives the fully discontinuous one (one node per
// cell corner). A fracture scene connects every edge where no crack may form, so the unknowns
// split only where the scene needs them to. The constructor numbers the nodes in order of their
// first pair (cell by cell, vertex by vertex), so its numbering depends only on the mesh and the
// edge set.
//
// A class only ever holds pairs at one mesh vertex, so when edges are disconnected only the
// classes at their end vertices change. `disconnect` re-classes those alone: every node keeps its
// number (the class that holds its smallest pair keeps it) and the classes split off are
// appended. The classes are those the constructor would build from the new edge set; only the
// numbers of the appended nodes differ. Nothing outside the touched vertices is visited, so an
// explicit run that cracks at every step pays for its cracks, not for its mesh.
//
// Per vertex the map keeps its nodes and its pairs grouped by node (one slot per pair at the
// vertex, so a vertex never needs more room than it has), which is what lets a split stay local.
#include <span>
#include <vector>

#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

class StateArchive;

class SplitDofMap {
 public:
  /// `connected[e]` (one entry per mesh edge; boundary entries are ignored) joins the two cells'
  /// copies of edge e's end vertices.
  SplitDofMap(const PolygonMesh& mesh, const std::vector<char>& connected);
  /// What a disconnect changed.
  struct Split {
    /// Per appended node (numbered from the old num_nodes() on), the node it split from.
    std::vector<int> source;
    /// Every node at a re-classed vertex, ascending: their pair lists may have changed.
    std::vector<int> nodes;
    /// The re-classed vertices (the disconnected edges' ends), ascending.
    std::vector<int> vertices;
  };
  /// The same classes after `edges` were disconnected: `connected` is the new edge set (those
  /// edges off, every other flag as before). Throws InputError for an edge out of range, or if
  /// the new edge set joins two nodes (a merge is not a disconnect).
  Split disconnect(const PolygonMesh& mesh, const std::vector<char>& connected,
                   std::span<const int> edges);
  /// Every interior edge connected (CG) or none (full DG).
  static SplitDofMap continuous(const PolygonMesh& mesh);
  static SplitDofMap discontinuous(const PolygonMesh& mesh);

  int num_nodes() const { return num_nodes_; }
  int num_dofs() const { return 2 * num_nodes_; }
  /// The node of cell c's vertex k (k in the cell's loop order).
  int node(int c, int k) const { return node_[offsets_[c] + k]; }
  /// The node of every pair (CSR like the cells' loops: pair offsets()[c] + k).
  std::span<const int> pair_nodes() const { return node_; }
  /// The nodes at mesh vertex v (one per class of its cells' copies), ascending.
  std::span<const int> vertex_nodes(int v) const {
    return {vertex_nodes_.data() + vertex_offsets_[v], std::size_t(vertex_node_count_[v])};
  }
  /// The pairs of node i, increasing.
  std::span<const int> node_pairs(int i) const {
    return {vertex_pairs_.data() + node_start_[i], std::size_t(node_count_[i])};
  }
  /// Whether interior edge e joins its cells: both end vertices share their nodes.
  bool joins(const PolygonMesh& mesh, int e) const;

  /// Saves or loads the whole map (a checkpoint: a rebuilt map could number its nodes otherwise).
  void archive(StateArchive& a);

 private:
  /// Rewrites vertex v's slots from node_: its nodes ascending, each node's pairs increasing.
  void index_vertex(int v);
  /// Re-classes the pairs at vertex v under the edge set `connected`: the class holding a
  /// node's smallest pair keeps its number, the others are appended (their sources to `split`).
  void reclass(const PolygonMesh& mesh, const std::vector<char>& connected, int v, Split& split);

  std::vector<int> offsets_;  // the mesh's cell offsets
  std::vector<int> node_;     // per (cell, vertex) pair, CSR like the cells' loops
  // Per vertex v its slots [vertex_offsets_[v], vertex_offsets_[v + 1]), one per pair at v:
  // vertex_pairs_ holds the pairs grouped by node ascending, vertex_nodes_ the nodes ascending
  // in the first vertex_node_count_[v] slots.
  std::vector<int> vertex_offsets_, vertex_pairs_, vertex_nodes_, vertex_node_count_;
  std::vector<int> node_start_, node_count_;  // node i's pairs in vertex_pairs_
  int num_nodes_ = 0;
};

}  // namespace vorodg
