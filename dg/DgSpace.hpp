#pragma once
// The discontinuous space: every cell owns a copy of each of its vertices' two DOFs, and every
// interior edge is an interface between the copies of its two cells. With cells 1 and 2 on an
// edge (cell 1 the edge's first cell, traversing it v0 -> v1), n is cell 1's outward normal and
// the jump is [u] = u_1 - u_2. Shape functions are linear along edges, so on an interface only
// the two end vertices' copies of each cell enter.
#include <Eigen/Core>
#include <vector>

#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

struct Interface {
  int edge;
  int cell[2];             // cell 1 (edge.cell0) and cell 2
  int dof_v0[2];           // first DOF (x) of vertex v0's copy in each cell
  int dof_v1[2];           // first DOF (x) of vertex v1's copy in each cell
  int local_edge[2];       // the edge's index in each cell (edge k runs from vertex k to k + 1)
  Eigen::Vector2d a, b;    // end points v0 and v1
  Eigen::Vector2d normal;  // outward from cell 1
  double length;
  double h_local;  // (area of cell 1 + area of cell 2) / (2 length)
};

class DgSpace {
 public:
  explicit DgSpace(const PolygonMesh& mesh);

  const PolygonMesh& mesh() const { return mesh_; }
  int num_dofs() const { return offsets_.back(); }
  /// First DOF of cell c (its copy of vertex k has DOFs first + 2k, first + 2k + 1).
  int cell_offset(int c) const { return offsets_[c]; }
  int cell_dof_count(int c) const { return offsets_[c + 1] - offsets_[c]; }
  const std::vector<Interface>& interfaces() const { return interfaces_; }
  /// Interfaces (interior edges) of cell c: the faces its interior-penalty terms live on.
  int interface_count(int c) const { return interface_count_[c]; }

 private:
  const PolygonMesh& mesh_;
  std::vector<int> offsets_;
  std::vector<Interface> interfaces_;
  std::vector<int> interface_count_;
};

}  // namespace vorodg
