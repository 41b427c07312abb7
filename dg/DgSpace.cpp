#include "dg/DgSpace.hpp"

#include <algorithm>

namespace vorodg {

DgSpace::DgSpace(const PolygonMesh& mesh) : mesh_(mesh) {
  offsets_.assign(mesh.num_cells() + 1, 0);
  for (int c = 0; c < mesh.num_cells(); ++c) offsets_[c + 1] = offsets_[c] + 2 * mesh.cell_size(c);
  auto local = [&](int c, int v) {
    const auto loop = mesh.cell_vertices(c);
    return static_cast<int>(std::find(loop.begin(), loop.end(), v) - loop.begin());
  };
  interface_count_.assign(mesh.num_cells(), 0);
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const MeshEdge& edge = mesh.edge(e);
    if (edge.on_boundary()) continue;
    Interface f;
    f.edge = e;
    f.cell[0] = edge.cell0;
    f.cell[1] = edge.cell1;
    for (int s = 0; s < 2; ++s) {
      f.dof_v0[s] = offsets_[f.cell[s]] + 2 * local(f.cell[s], edge.v0);
      f.dof_v1[s] = offsets_[f.cell[s]] + 2 * local(f.cell[s], edge.v1);
    }
    // Cell 1 runs the edge v0 -> v1 (its edge starts at v0), cell 2 runs it v1 -> v0.
    f.local_edge[0] = local(f.cell[0], edge.v0);
    f.local_edge[1] = local(f.cell[1], edge.v1);
    f.a = mesh.vertex(edge.v0);
    f.b = mesh.vertex(edge.v1);
    const Eigen::Vector2d t = f.b - f.a;
    f.length = t.norm();
    f.normal = Eigen::Vector2d(t.y(), -t.x()) / f.length;  // cell 1 runs v0 -> v1 counter-clockwise
    f.h_local = (mesh.cell_area(f.cell[0]) + mesh.cell_area(f.cell[1])) / (2.0 * f.length);
    interfaces_.push_back(f);
    ++interface_count_[f.cell[0]];
    ++interface_count_[f.cell[1]];
  }
}

}  // namespace vorodg
