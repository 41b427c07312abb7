#pragma once
// Shape statistics of a mesh: what a user checks before trusting it.
#include <map>

#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

struct MeshStatistics {
  int cells = 0;
  int vertices = 0;
  int edges = 0;
  int boundary_edges = 0;
  double h_avg = 0.0;
  double min_edge = 0.0;
  double max_edge = 0.0;
  double min_edge_over_h = 0.0;
  double min_interior_angle_deg = 0.0;
  double max_interior_angle_deg = 0.0;
  double area_error = 0.0;         // |sum of cell areas - domain area| / domain area
  std::map<int, int> side_counts;  // number of cells with k sides
  int most_common_sides = 0;
};

MeshStatistics compute_statistics(const PolygonMesh& mesh);

/// Histogram of the number of sides per cell.
std::map<int, int> side_count_histogram(const PolygonMesh& mesh);

}  // namespace vorodg
