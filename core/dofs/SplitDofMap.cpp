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
  UnionFind pairs(offsets_.back());
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const MeshEdge& edge = mesh.edge(e);
    if (edge.on_boundary() || !connected[e]) continue;
    for (int v : {edge.v0, edge.v1})
      pairs.join(offsets_[edge.cell0] + local_index(mesh, edge.cell0, v),
                 offsets_[edge.cell1] + local_index(mesh, edge.cell1, v));
  }
  node_ = pairs.labels(&num_nodes_);  // numbered in order of each class's smallest pair
  vertex_offsets_.assign(mesh.num_vertices() + 1, 0);
  std::vector<std::vector<int>> at(mesh.num_vertices());
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto loop = mesh.cell_vertices(c);
    for (std::size_t k = 0; k < loop.size(); ++k) at[loop[k]].push_back(node(c, int(k)));
  }
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    std::sort(at[v].begin(), at[v].end());
    at[v].erase(std::unique(at[v].begin(), at[v].end()), at[v].end());
    vertex_offsets_[v + 1] = vertex_offsets_[v] + static_cast<int>(at[v].size());
    vertex_nodes_.insert(vertex_nodes_.end(), at[v].begin(), at[v].end());
  }
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
