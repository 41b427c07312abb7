#pragma once
// The crack network as a graph (report section 7). In the report's words the crack lives on the
// Delaunay dual of the seeds: the cells are Voronoi cells, their edges are Voronoi edges, and a
// crack runs along them. So the cracked Voronoi (mesh) edges form a graph whose nodes are the
// Voronoi (mesh) vertices. Its connected components (union-find over the vertices) are the
// separate crack branches; a component that touches two opposite sides of the rectangle domain
// is a crack that spans the body.
//
// Only vertices with at least one cracked edge belong to a component; the others are left out
// of the count. Cracked edges are interior edges, so a crack "touches" a side when one of its
// vertices lies on that side's line, within the mesh's tag tolerance x the domain's scale (the
// test that tags the boundary edges).
#include <array>
#include <vector>

#include "core/geometry/Rectangle.hpp"
#include "fracture/CrackState.hpp"

namespace vorodg {

class CrackGraph {
 public:
  explicit CrackGraph(const CrackState& cracks);

  /// Number of crack components (0 when nothing is cracked).
  int num_components() const { return num_components_; }
  /// The component of mesh vertex v, numbered in order of the components' smallest vertex, or
  /// -1 if no cracked edge ends at v.
  int component(int v) const { return component_[v]; }
  /// Number of cracked edges in each component.
  const std::vector<int>& component_edges() const { return edges_; }
  /// Whether component k has a vertex on side s.
  bool touches(int k, Side s) const;
  /// Whether some component touches both sides a and b (e.g. left and right, or bottom and top:
  /// a crack that spans the body). Throws InputError for Side::none.
  bool spans(Side a, Side b) const;

 private:
  int num_components_ = 0;
  std::vector<int> component_;
  std::vector<int> edges_;
  std::vector<std::array<bool, 4>> sides_;  // per component, per side
};

}  // namespace vorodg
