#pragma once
// The discontinuous space: cell c's vertex k has the two DOFs dof(c, k), dof(c, k) + 1, and every
// interior edge whose cells do not share their vertices' DOFs is an interface between them. In the
// full DG space every cell owns a copy of each of its vertices (cell c's DOFs are contiguous); a
// SplitDofMap gives the spaces in between, where only crack-capable edges are interfaces. With
// cells 1 and 2 on an edge (cell 1 the edge's first cell, traversing it v0 -> v1), n is cell 1's
// outward normal and the jump is [u] = u_1 - u_2. Shape functions are linear along edges, so on
// an interface only the two end vertices' DOFs of each cell enter.
#include <Eigen/Core>
#include <vector>

#include "core/dofs/SplitDofMap.hpp"
#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

struct Interface {
  int edge;
  int cell[2];             // cell 1 (edge.cell0) and cell 2
  int dof_v0[2];           // first DOF (x) of vertex v0 in each cell
  int dof_v1[2];           // first DOF (x) of vertex v1 in each cell
  int local_edge[2];       // the edge's index in each cell (edge k runs from vertex k to k + 1)
  Eigen::Vector2d a, b;    // end points v0 and v1
  Eigen::Vector2d normal;  // outward from cell 1
  double length;
  double h_local;  // (area of cell 1 + area of cell 2) / (2 length)
};

class DgSpace {
 public:
  /// The full DG space: every interior edge is an interface.
  explicit DgSpace(const PolygonMesh& mesh);
  /// The space of a split DOF map: interfaces are the interior edges it does not join.
  DgSpace(const PolygonMesh& mesh, const SplitDofMap& map);

  const PolygonMesh& mesh() const { return mesh_; }
  int num_dofs() const { return num_dofs_; }
  /// First DOF (x) of cell c's vertex k; y follows it.
  int dof(int c, int k) const { return dof_[mesh_.offsets()[c] + k]; }
  int cell_dof_count(int c) const { return 2 * mesh_.cell_size(c); }
  /// Cell c's DOFs in the integrator's order ((x, y) per vertex of its loop).
  std::vector<int> cell_dofs(int c) const;
  const std::vector<Interface>& interfaces() const { return interfaces_; }
  /// Interfaces of cell c: the faces its interior-penalty terms live on.
  int interface_count(int c) const { return interface_count_[c]; }

 private:
  void build_interfaces(const std::vector<char>& is_interface);

  const PolygonMesh& mesh_;
  std::vector<int> dof_;  // per (cell, vertex) pair, in the mesh's CSR order
  int num_dofs_ = 0;
  std::vector<Interface> interfaces_;
  std::vector<int> interface_count_;
};

}  // namespace vorodg
