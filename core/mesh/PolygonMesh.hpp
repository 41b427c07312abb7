#pragma once
// The polygon mesh every stage works on: vertices, counter-clockwise cells, unique edges with
// their one or two cells, and boundary edges tagged by the side of the rectangle domain they lie
// on. Topology queries (cells of a vertex, edges of a cell, neighbour across an edge) are O(1)
// after construction. The mesh is immutable: generators build a new one.
#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

#include "core/geometry/Rectangle.hpp"

namespace vorodg {

/// An edge v0 -> v1 as traversed by cell0 (counter-clockwise). cell1 traverses it v1 -> v0, or
/// is -1 on the boundary, where `side` says which side of the domain the edge lies on.
struct MeshEdge {
  int v0 = -1;
  int v1 = -1;
  int cell0 = -1;
  int cell1 = -1;
  Side side = Side::none;
  bool on_boundary() const { return cell1 < 0; }
};

/// A topological inconsistency met while building the edges (reported by MeshValidator).
struct TopologyDefect {
  enum class Kind { non_manifold_edge, inconsistent_orientation, degenerate_edge };
  Kind kind;
  int v0, v1;        // the edge's vertices
  std::string what;  // one line, with the cells involved
};

class PolygonMesh {
 public:
  PolygonMesh() = default;
  /// Cells are given in CSR form: cell c has vertices cell_vertices[offsets[c] .. offsets[c+1]).
  /// Boundary edges are tagged against `domain` with tolerance `tag_tolerance` x domain.scale().
  /// Throws InputError only for index errors (offsets not increasing, vertex out of range);
  /// geometric and manifold defects are recorded for MeshValidator instead.
  PolygonMesh(Rectangle domain, std::vector<Point> vertices, std::vector<int> offsets,
              std::vector<int> cell_vertices, double tag_tolerance = kDefaultTagTolerance);

  static constexpr double kDefaultTagTolerance = 1e-8;

  const Rectangle& domain() const { return domain_; }
  int num_vertices() const { return static_cast<int>(vertices_.size()); }
  int num_cells() const { return static_cast<int>(offsets_.size()) - 1; }
  int num_edges() const { return static_cast<int>(edges_.size()); }

  const Point& vertex(int v) const { return vertices_[v]; }
  const std::vector<Point>& vertices() const { return vertices_; }
  /// Vertex loop of cell c, counter-clockwise for a valid mesh.
  std::span<const int> cell_vertices(int c) const {
    return {cell_vertices_.data() + offsets_[c], cell_vertices_.data() + offsets_[c + 1]};
  }
  int cell_size(int c) const { return offsets_[c + 1] - offsets_[c]; }
  /// Edge k of cell c joins cell_vertices(c)[k] and cell_vertices(c)[k+1].
  std::span<const int> cell_edges(int c) const {
    return {cell_edges_.data() + offsets_[c], cell_edges_.data() + offsets_[c + 1]};
  }
  /// Cells that contain vertex v.
  std::span<const int> vertex_cells(int v) const {
    return {vertex_cells_.data() + vertex_cell_offsets_[v],
            vertex_cells_.data() + vertex_cell_offsets_[v + 1]};
  }
  const MeshEdge& edge(int e) const { return edges_[e]; }
  const std::vector<MeshEdge>& edges() const { return edges_; }
  /// The vertices of the edges on one side of the domain, in increasing order.
  std::vector<int> side_vertices(Side side) const;
  /// Cell across local edge k of cell c, or -1 on the boundary.
  int neighbor(int c, int k) const;

  /// Coordinates of cell c's loop (a copy; for geometry kernels).
  std::vector<Point> cell_points(int c) const;
  double cell_area(int c) const;
  Point cell_centroid(int c) const;
  double total_area() const;
  /// Mesh size used on every convergence plot: sqrt(domain area / number of cells).
  double h_avg() const;
  double edge_length(int e) const {
    return (vertices_[edges_[e].v1] - vertices_[edges_[e].v0]).norm();
  }

  const std::vector<int>& offsets() const { return offsets_; }
  const std::vector<int>& cell_vertex_list() const { return cell_vertices_; }
  const std::vector<TopologyDefect>& topology_defects() const { return topology_defects_; }
  double tag_tolerance() const { return tag_tolerance_; }

 private:
  void check_indices() const;
  void build_vertex_cells();
  void build_edges();
  void tag_boundary_edges();

  Rectangle domain_;
  double tag_tolerance_ = kDefaultTagTolerance;
  std::vector<Point> vertices_;
  std::vector<int> offsets_{0};
  std::vector<int> cell_vertices_;
  std::vector<int> cell_edges_;
  std::vector<int> vertex_cell_offsets_;
  std::vector<int> vertex_cells_;
  std::vector<MeshEdge> edges_;
  std::vector<TopologyDefect> topology_defects_;
};

}  // namespace vorodg
