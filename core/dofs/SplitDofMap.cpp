#include "core/dofs/SplitDofMap.hpp"

#include <algorithm>

#include "core/util/Errors.hpp"
#include "core/util/UnionFind.hpp"

namespace vorodg {
namespace {

/// Position of vertex v in cell c's loop.
int local_index(const PolygonMesh& mesh, int c, int v) {
  const auto loop = mesh.cell_vertices(c);
  return static_cast<int>(std::find(loop.begin(), loop.end(), v) - loop.begin());
}

}  // namespace

SplitDofMap::SplitDofMap(const PolygonMesh& mesh, const std::vector<char>& connected)
    : offsets_(mesh.offsets()) {
  if (static_cast<int>(connected.size()) != mesh.num_edges())
    throw InputError("split DOF map: " + std::to_string(connected.size()) +
                     " edge flags for a mesh of " + std::to_string(mesh.num_edges()) + " edges");
  // Each edge's local position in its two cells, from one pass over the cells' edge loops (a
  // remap rebuilds this map after every step that cracks, so no loop is searched per edge).
  std::vector<int> local0(mesh.num_edges(), -1), local1(mesh.num_edges(), -1);
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto edges = mesh.cell_edges(c);
    for (int k = 0; k < static_cast<int>(edges.size()); ++k)
      (mesh.edge(edges[k]).cell0 == c ? local0 : local1)[edges[k]] = k;
  }
  // The pairs of cell c at the ends of its local edge k hold vertex v: k or k + 1.
  auto pair_of = [&](int c, int k, int v) {
    const int n = mesh.cell_size(c), next = (k + 1) % n;
    return offsets_[c] + (mesh.cell_vertices(c)[k] == v ? k : next);
  };
  UnionFind pairs(offsets_.back());
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const MeshEdge& edge = mesh.edge(e);
    if (edge.on_boundary() || !connected[e]) continue;
    for (int v : {edge.v0, edge.v1})
      pairs.join(pair_of(edge.cell0, local0[e], v), pair_of(edge.cell1, local1[e], v));
  }
  node_ = pairs.labels(&num_nodes_);  // numbered in order of each class's smallest pair
  // Per vertex its nodes, ascending: the pairs bucketed by vertex, then sorted and deduplicated
  // in place.
  const std::vector<int>& vertex_of_pair = mesh.cell_vertex_list();
  const int nv = mesh.num_vertices();
  vertex_offsets_.assign(nv + 1, 0);
  for (int v : vertex_of_pair) ++vertex_offsets_[v + 1];
  for (int v = 0; v < nv; ++v) vertex_offsets_[v + 1] += vertex_offsets_[v];
  vertex_nodes_.resize(vertex_of_pair.size());
  std::vector<int> next(vertex_offsets_.begin(), vertex_offsets_.end() - 1);
  for (std::size_t p = 0; p < vertex_of_pair.size(); ++p)
    vertex_nodes_[next[vertex_of_pair[p]]++] = node_[p];
  int read = 0, write = 0;
  for (int v = 0; v < nv; ++v) {
    const int end = vertex_offsets_[v + 1];
    std::sort(vertex_nodes_.begin() + read, vertex_nodes_.begin() + end);
    const int last =
        static_cast<int>(std::unique(vertex_nodes_.begin() + read, vertex_nodes_.begin() + end) -
                         vertex_nodes_.begin());
    vertex_offsets_[v] = write;
    for (int p = read; p < last; ++p) vertex_nodes_[write++] = vertex_nodes_[p];
    read = end;
  }
  vertex_offsets_[nv] = write;
  vertex_nodes_.resize(write);
}

SplitDofMap SplitDofMap::continuous(const PolygonMesh& mesh) {
  return SplitDofMap(mesh, std::vector<char>(mesh.num_edges(), 1));
}

SplitDofMap SplitDofMap::discontinuous(const PolygonMesh& mesh) {
  return SplitDofMap(mesh, std::vector<char>(mesh.num_edges(), 0));
}

bool SplitDofMap::joins(const PolygonMesh& mesh, int e) const {
  const MeshEdge& edge = mesh.edge(e);
  if (edge.on_boundary()) return false;
  for (int v : {edge.v0, edge.v1})
    if (node(edge.cell0, local_index(mesh, edge.cell0, v)) !=
        node(edge.cell1, local_index(mesh, edge.cell1, v)))
      return false;
  return true;
}

}  // namespace vorodg
