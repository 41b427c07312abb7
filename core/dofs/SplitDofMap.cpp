#include "core/dofs/SplitDofMap.hpp"

#include <algorithm>

#include "core/io/StateArchive.hpp"
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
  // Nodes in order of their first pair: a class's root is its smallest pair, so its node is
  // known by the time its later pairs come.
  const int np = offsets_.back();
  node_.resize(np);
  for (int p = 0; p < np; ++p) {
    const int root = pairs.root(p);
    node_[p] = root == p ? num_nodes_++ : node_[root];
  }
  // Each vertex's slots, one per pair at it (a counting sort of the pairs by vertex).
  const std::vector<int>& vertex_of_pair = mesh.cell_vertex_list();
  const int nv = mesh.num_vertices();
  vertex_offsets_.assign(nv + 1, 0);
  for (int p = 0; p < np; ++p) ++vertex_offsets_[vertex_of_pair[p] + 1];
  for (int v = 0; v < nv; ++v) vertex_offsets_[v + 1] += vertex_offsets_[v];
  vertex_pairs_.resize(np);
  std::vector<int> next(vertex_offsets_.begin(), vertex_offsets_.end() - 1);
  for (int p = 0; p < np; ++p) vertex_pairs_[next[vertex_of_pair[p]]++] = p;
  vertex_nodes_.resize(np);
  vertex_node_count_.assign(nv, 0);
  node_start_.resize(num_nodes_);
  node_count_.resize(num_nodes_);
  for (int v = 0; v < nv; ++v) index_vertex(v);
}

void SplitDofMap::index_vertex(int v) {
  const auto first = vertex_pairs_.begin() + vertex_offsets_[v];
  const auto last = vertex_pairs_.begin() + vertex_offsets_[v + 1];
  std::sort(first, last,
            [&](int a, int b) { return node_[a] != node_[b] ? node_[a] < node_[b] : a < b; });
  int* nodes = vertex_nodes_.data() + vertex_offsets_[v];
  int count = 0;
  for (auto it = first; it != last; ++it) {
    const int i = node_[*it];
    if (count == 0 || nodes[count - 1] != i) {
      nodes[count++] = i;
      node_start_[i] = static_cast<int>(it - vertex_pairs_.begin());
      node_count_[i] = 0;
    }
    ++node_count_[i];
  }
  vertex_node_count_[v] = count;
}

SplitDofMap::Split SplitDofMap::disconnect(const PolygonMesh& mesh,
                                           const std::vector<char>& connected,
                                           std::span<const int> edges) {
  if (static_cast<int>(connected.size()) != mesh.num_edges())
    throw InputError("split DOF map: " + std::to_string(connected.size()) +
                     " edge flags for a mesh of " + std::to_string(mesh.num_edges()) + " edges");
  std::vector<int> vertices;
  for (int e : edges) {
    if (e < 0 || e >= mesh.num_edges())
      throw InputError("split DOF map: edge " + std::to_string(e) + " out of range [0, " +
                       std::to_string(mesh.num_edges()) + ")");
    vertices.push_back(mesh.edge(e).v0);
    vertices.push_back(mesh.edge(e).v1);
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  Split split;
  for (int v : vertices) reclass(mesh, connected, v, split);
  node_start_.resize(num_nodes_);
  node_count_.resize(num_nodes_);
  for (int v : vertices) {
    index_vertex(v);
    const auto nodes = vertex_nodes(v);
    split.nodes.insert(split.nodes.end(), nodes.begin(), nodes.end());
  }
  std::sort(split.nodes.begin(), split.nodes.end());
  split.vertices = std::move(vertices);
  return split;
}

void SplitDofMap::reclass(const PolygonMesh& mesh, const std::vector<char>& connected, int v,
                          Split& split) {
  // The cells at v in increasing order, so their pairs are increasing too (pairs are CSR by
  // cell), and a union-find over their positions: a class's root is its smallest pair.
  const auto around_v = mesh.vertex_cells(v);
  std::vector<int> cells(around_v.begin(), around_v.end());
  std::sort(cells.begin(), cells.end());
  const int n = static_cast<int>(cells.size());
  std::vector<int> pair(n);
  for (int i = 0; i < n; ++i) pair[i] = offsets_[cells[i]] + local_index(mesh, cells[i], v);
  UnionFind around(n);
  for (int i = 0; i < n; ++i) {
    // The two edges of cell i at v: its local edges k - 1 and k, k the position of v.
    const int c = cells[i], k = pair[i] - offsets_[c], size = mesh.cell_size(c);
    for (int e : {mesh.cell_edges(c)[k], mesh.cell_edges(c)[(k + size - 1) % size]}) {
      const MeshEdge& edge = mesh.edge(e);
      if (edge.on_boundary() || !connected[e]) continue;
      const int other = edge.cell0 == c ? edge.cell1 : edge.cell0;
      const auto j = std::lower_bound(cells.begin(), cells.end(), other) - cells.begin();
      around.join(i, static_cast<int>(j));
    }
  }
  // Classes in order of their smallest pair; the first to hold a node's pairs keeps its number.
  std::vector<int> number(n, -1);
  for (int i = 0; i < n; ++i) {
    const int root = around.root(i), old = node_[pair[i]];
    if (node_[pair[root]] != old)
      throw InputError("split DOF map: the edge set joins nodes " + std::to_string(old) + " and " +
                       std::to_string(node_[pair[root]]) + " at vertex " + std::to_string(v) +
                       ": a disconnect may only turn edges off");
    if (root != i) continue;
    bool kept = false;
    for (int j = 0; j < i; ++j) kept = kept || (number[j] == old);
    number[i] = kept ? num_nodes_++ : old;
    if (kept) split.source.push_back(old);
  }
  for (int i = 0; i < n; ++i) node_[pair[i]] = number[around.root(i)];
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

void SplitDofMap::archive(StateArchive& a) {
  a.vector("dofs.offsets", offsets_);
  a.vector("dofs.node", node_);
  a.vector("dofs.vertex_offsets", vertex_offsets_);
  a.vector("dofs.vertex_pairs", vertex_pairs_);
  a.vector("dofs.vertex_nodes", vertex_nodes_);
  a.vector("dofs.vertex_node_count", vertex_node_count_);
  a.vector("dofs.node_start", node_start_);
  a.vector("dofs.node_count", node_count_);
  a.value("dofs.num_nodes", num_nodes_);
}

}  // namespace vorodg
