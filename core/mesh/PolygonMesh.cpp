#include "core/mesh/PolygonMesh.hpp"

#include <algorithm>
#include <cmath>

#include "core/geometry/Polygon.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {

PolygonMesh::PolygonMesh(Rectangle domain, std::vector<Point> vertices, std::vector<int> offsets,
                         std::vector<int> cell_vertices, double tag_tolerance)
    : domain_(domain),
      tag_tolerance_(tag_tolerance),
      vertices_(std::move(vertices)),
      offsets_(std::move(offsets)),
      cell_vertices_(std::move(cell_vertices)) {
  check_indices();
  build_vertex_cells();
  build_edges();
  tag_boundary_edges();
}

void PolygonMesh::check_indices() const {
  if (offsets_.empty() || offsets_.front() != 0)
    throw InputError("mesh: cell offsets must start at 0");
  if (offsets_.back() != static_cast<int>(cell_vertices_.size()))
    throw InputError("mesh: last cell offset " + std::to_string(offsets_.back()) +
                     " does not match the connectivity length " +
                     std::to_string(cell_vertices_.size()));
  for (std::size_t c = 0; c + 1 < offsets_.size(); ++c)
    if (offsets_[c + 1] - offsets_[c] < 3)
      throw InputError("mesh: cell " + std::to_string(c) + " has " +
                       std::to_string(offsets_[c + 1] - offsets_[c]) +
                       " vertices, expected at least 3");
  for (std::size_t i = 0; i < cell_vertices_.size(); ++i)
    if (cell_vertices_[i] < 0 || cell_vertices_[i] >= static_cast<int>(vertices_.size()))
      throw InputError("mesh: connectivity entry " + std::to_string(i) + " refers to vertex " +
                       std::to_string(cell_vertices_[i]) + ", expected 0.." +
                       std::to_string(static_cast<long>(vertices_.size()) - 1));
}

void PolygonMesh::build_vertex_cells() {
  const int nv = num_vertices();
  vertex_cell_offsets_.assign(nv + 1, 0);
  for (int v : cell_vertices_) ++vertex_cell_offsets_[v + 1];
  for (int v = 0; v < nv; ++v) vertex_cell_offsets_[v + 1] += vertex_cell_offsets_[v];
  vertex_cells_.resize(cell_vertices_.size());
  std::vector<int> fill(vertex_cell_offsets_.begin(), vertex_cell_offsets_.end() - 1);
  for (int c = 0; c < num_cells(); ++c)
    for (int v : cell_vertices(c)) vertex_cells_[fill[v]++] = c;
}

// Edges are found in O(#edges): every cell edge is filed under its smaller vertex, and the few
// edges filed under one vertex are matched by a linear scan.
void PolygonMesh::build_edges() {
  const int nv = num_vertices();
  cell_edges_.assign(cell_vertices_.size(), -1);
  std::vector<int> first(nv, -1);  // first edge filed under each vertex
  std::vector<int> next;           // next edge filed under the same vertex
  edges_.clear();
  edges_.reserve(cell_vertices_.size() / 2 + num_cells());
  next.reserve(edges_.capacity());
  for (int c = 0; c < num_cells(); ++c) {
    const int begin = offsets_[c];
    const int n = cell_size(c);
    for (int k = 0; k < n; ++k) {
      const int a = cell_vertices_[begin + k];
      const int b = cell_vertices_[begin + (k + 1) % n];
      if (a == b) {
        topology_defects_.push_back({TopologyDefect::Kind::degenerate_edge, a, b,
                                     "cell " + std::to_string(c) + " repeats vertex " +
                                         std::to_string(a) + " on consecutive positions"});
        continue;
      }
      const int key = std::min(a, b);
      const int other = std::max(a, b);
      int found = -1;
      for (int e = first[key]; e >= 0; e = next[e])
        if (std::max(edges_[e].v0, edges_[e].v1) == other) {
          found = e;
          break;
        }
      if (found < 0) {
        found = static_cast<int>(edges_.size());
        edges_.push_back({a, b, c, -1, Side::none});
        next.push_back(first[key]);
        first[key] = found;
      } else {
        MeshEdge& edge = edges_[found];
        auto where = [&] { return "edge (" + std::to_string(a) + "," + std::to_string(b) + ")"; };
        if (edge.cell1 >= 0) {
          topology_defects_.push_back({TopologyDefect::Kind::non_manifold_edge, a, b,
                                       where() + " is shared by cells " +
                                           std::to_string(edge.cell0) + ", " +
                                           std::to_string(edge.cell1) + " and " +
                                           std::to_string(c) + ", expected at most two"});
        } else if (edge.v0 == a) {
          topology_defects_.push_back({TopologyDefect::Kind::inconsistent_orientation, a, b,
                                       where() + " is traversed in the same direction by cells " +
                                           std::to_string(edge.cell0) + " and " +
                                           std::to_string(c) + ", expected opposite"});
          edge.cell1 = c;
        } else {
          edge.cell1 = c;
        }
      }
      cell_edges_[begin + k] = found;
    }
  }
}

void PolygonMesh::tag_boundary_edges() {
  const double tol = tag_tolerance_ * domain_.scale();
  for (MeshEdge& e : edges_)
    if (e.on_boundary()) e.side = domain_.common_side(vertices_[e.v0], vertices_[e.v1], tol);
}

int PolygonMesh::neighbor(int c, int k) const {
  const MeshEdge& e = edges_[cell_edges_[offsets_[c] + k]];
  return e.cell0 == c ? e.cell1 : e.cell0;
}

std::vector<Point> PolygonMesh::cell_points(int c) const {
  std::vector<Point> pts;
  pts.reserve(cell_size(c));
  for (int v : cell_vertices(c)) pts.push_back(vertices_[v]);
  return pts;
}

double PolygonMesh::cell_area(int c) const {
  return polygon::signed_area(cell_points(c));
}

Point PolygonMesh::cell_centroid(int c) const {
  const auto pts = cell_points(c);
  return polygon::centroid(pts, polygon::signed_area(pts));
}

double PolygonMesh::total_area() const {
  double sum = 0.0;
  for (int c = 0; c < num_cells(); ++c) sum += cell_area(c);
  return sum;
}

double PolygonMesh::h_avg() const {
  return num_cells() > 0 ? std::sqrt(domain_.area() / num_cells()) : 0.0;
}

std::vector<int> PolygonMesh::side_vertices(Side side) const {
  std::vector<char> on(num_vertices(), 0);
  for (const MeshEdge& e : edges_)
    if (e.side == side) on[e.v0] = on[e.v1] = 1;
  std::vector<int> out;
  for (int v = 0; v < num_vertices(); ++v)
    if (on[v]) out.push_back(v);
  return out;
}

}  // namespace vorodg
