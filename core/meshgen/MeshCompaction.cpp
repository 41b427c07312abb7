#include "core/meshgen/MeshCompaction.hpp"

#include "core/util/UnionFind.hpp"

namespace vorodg {

PolygonMesh compact_mesh(const PolygonMesh& like, std::span<const Point> positions,
                         const std::vector<std::span<const int>>& loops) {
  std::vector<int> new_id(positions.size(), -1);
  for (auto loop : loops)
    for (int v : loop) new_id[v] = 0;
  std::vector<Point> vertices;
  for (std::size_t v = 0; v < positions.size(); ++v)
    if (new_id[v] == 0) {
      new_id[v] = static_cast<int>(vertices.size());
      vertices.push_back(positions[v]);
    }
  std::vector<int> offsets{0}, cells;
  for (auto loop : loops) {
    for (int v : loop) cells.push_back(new_id[v]);
    offsets.push_back(static_cast<int>(cells.size()));
  }
  return PolygonMesh(like.domain(), std::move(vertices), std::move(offsets), std::move(cells),
                     like.tag_tolerance());
}

PolygonMesh merge_coincident_vertices(const PolygonMesh& mesh, double tol, int& merged) {
  UnionFind vertices(mesh.num_vertices());  // a class's root is its smallest id
  merged = 0;
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const int a = mesh.edge(e).v0, b = mesh.edge(e).v1;
    if (!(mesh.edge_length(e) <= tol) || vertices.root(a) == vertices.root(b)) continue;
    vertices.join(a, b);
    ++merged;
  }
  if (merged == 0) return mesh;
  std::vector<std::vector<int>> loops(mesh.num_cells());
  for (int c = 0; c < mesh.num_cells(); ++c) {
    for (int v : mesh.cell_vertices(c)) {
      const int root = vertices.root(v);
      if (loops[c].empty() || loops[c].back() != root) loops[c].push_back(root);
    }
    while (loops[c].size() > 1 && loops[c].back() == loops[c].front()) loops[c].pop_back();
  }
  const std::vector<std::span<const int>> spans(loops.begin(), loops.end());
  return compact_mesh(mesh, mesh.vertices(), spans);
}

}  // namespace vorodg
