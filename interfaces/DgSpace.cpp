#include "interfaces/DgSpace.hpp"

#include <algorithm>

namespace vorodg {

DgSpace::DgSpace(const PolygonMesh& mesh) : mesh_(mesh) {
  dof_.resize(mesh.offsets().back());
  for (std::size_t p = 0; p < dof_.size(); ++p) dof_[p] = 2 * static_cast<int>(p);
  num_dofs_ = 2 * static_cast<int>(dof_.size());
  std::vector<char> interior(mesh.num_edges());
  for (int e = 0; e < mesh.num_edges(); ++e) interior[e] = !mesh.edge(e).on_boundary();
  build_interfaces(interior);
}

DgSpace::DgSpace(const PolygonMesh& mesh, const SplitDofMap& map) : mesh_(mesh) {
  dof_.resize(mesh.offsets().back());
  for (int c = 0; c < mesh.num_cells(); ++c)
    for (int k = 0; k < mesh.cell_size(c); ++k) dof_[mesh.offsets()[c] + k] = 2 * map.node(c, k);
  num_dofs_ = map.num_dofs();
  std::vector<char> split(mesh.num_edges());
  for (int e = 0; e < mesh.num_edges(); ++e)
    split[e] = !mesh.edge(e).on_boundary() && !map.joins(mesh, e);
  build_interfaces(split);
}

std::vector<int> DgSpace::cell_dofs(int c) const {
  std::vector<int> out(cell_dof_count(c));
  for (int k = 0; k < mesh_.cell_size(c); ++k) {
    out[2 * k] = dof(c, k);
    out[2 * k + 1] = dof(c, k) + 1;
  }
  return out;
}

void DgSpace::build_interfaces(const std::vector<char>& is_interface) {
  const PolygonMesh& mesh = mesh_;
  auto local = [&](int c, int v) {
    const auto loop = mesh.cell_vertices(c);
    return static_cast<int>(std::find(loop.begin(), loop.end(), v) - loop.begin());
  };
  interface_count_.assign(mesh.num_cells(), 0);
  for (int e = 0; e < mesh.num_edges(); ++e) {
    if (!is_interface[e]) continue;
    const MeshEdge& edge = mesh.edge(e);
    Interface f;
    f.edge = e;
    f.cell[0] = edge.cell0;
    f.cell[1] = edge.cell1;
    for (int s = 0; s < 2; ++s) {
      f.dof_v0[s] = dof(f.cell[s], local(f.cell[s], edge.v0));
      f.dof_v1[s] = dof(f.cell[s], local(f.cell[s], edge.v1));
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
