#include "core/mesh/MeshStatistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/geometry/Polygon.hpp"

namespace vorodg {

std::map<int, int> side_count_histogram(const PolygonMesh& mesh) {
  std::map<int, int> histogram;
  for (int c = 0; c < mesh.num_cells(); ++c) ++histogram[mesh.cell_size(c)];
  return histogram;
}

MeshStatistics compute_statistics(const PolygonMesh& mesh) {
  MeshStatistics s;
  s.cells = mesh.num_cells();
  s.vertices = mesh.num_vertices();
  s.edges = mesh.num_edges();
  s.h_avg = mesh.h_avg();
  s.min_edge = std::numeric_limits<double>::infinity();
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const double len = mesh.edge_length(e);
    s.min_edge = std::min(s.min_edge, len);
    s.max_edge = std::max(s.max_edge, len);
    if (mesh.edge(e).on_boundary()) ++s.boundary_edges;
  }
  if (mesh.num_edges() == 0) s.min_edge = 0.0;
  s.min_edge_over_h = s.h_avg > 0 ? s.min_edge / s.h_avg : 0.0;
  double min_angle = 2 * std::numbers::pi, max_angle = 0.0, area = 0.0;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto pts = mesh.cell_points(c);
    area += polygon::signed_area(pts);
    min_angle = std::min(min_angle, polygon::min_interior_angle(pts));
    max_angle = std::max(max_angle, polygon::max_interior_angle(pts));
  }
  s.min_interior_angle_deg = mesh.num_cells() ? min_angle * 180.0 / std::numbers::pi : 0.0;
  s.max_interior_angle_deg = max_angle * 180.0 / std::numbers::pi;
  s.area_error = std::abs(area - mesh.domain().area()) / mesh.domain().area();
  s.side_counts = side_count_histogram(mesh);
  int best = 0;
  for (auto [sides, count] : s.side_counts)
    if (count > best) best = count, s.most_common_sides = sides;
  return s;
}

}  // namespace vorodg
