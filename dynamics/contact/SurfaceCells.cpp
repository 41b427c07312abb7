#include "dynamics/contact/SurfaceCells.hpp"

#include <algorithm>
#include <string>

#include "core/io/StateArchive.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {

SurfaceCells::SurfaceCells(const PolygonMesh& mesh)
    : mesh_(&mesh),
      member_(mesh.num_cells(), 0),
      exposed_(mesh.offsets().back(), 0),
      released_(mesh.num_edges(), 0) {
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto edges = mesh.cell_edges(c);
    for (std::size_t k = 0; k < edges.size(); ++k)
      if (mesh.edge(edges[k]).on_boundary()) exposed_[mesh.offsets()[c] + k] = 1;
    if (has_exposed_edge(c)) add(c);
  }
}

void SurfaceCells::check_cell(int cell) const {
  if (cell < 0 || cell >= mesh_->num_cells())
    throw InputError("surface cells: cell " + std::to_string(cell) + " out of range [0, " +
                     std::to_string(mesh_->num_cells()) + ")");
}

bool SurfaceCells::add(int cell) {
  check_cell(cell);
  if (member_[cell]) return false;
  member_[cell] = 1;
  cells_.push_back(cell);
  return true;
}

void SurfaceCells::check_edge(int edge) const {
  if (edge < 0 || edge >= mesh_->num_edges())
    throw InputError("surface cells: edge " + std::to_string(edge) + " out of range [0, " +
                     std::to_string(mesh_->num_edges()) + ")");
}

int SurfaceCells::local_index(int cell, int edge) const {
  const auto edges = mesh_->cell_edges(cell);
  return static_cast<int>(std::find(edges.begin(), edges.end(), edge) - edges.begin());
}

void SurfaceCells::expose(int edge) {
  check_edge(edge);
  const MeshEdge& e = mesh_->edge(edge);
  for (int c : {e.cell0, e.cell1}) {
    if (c < 0) continue;
    exposed_[mesh_->offsets()[c] + local_index(c, edge)] = 1;
    add(c);
  }
}

void SurfaceCells::release(int edge) {
  check_edge(edge);
  const MeshEdge& e = mesh_->edge(edge);
  if (e.on_boundary() || !exposed(e.cell0, local_index(e.cell0, edge)))
    throw InputError("surface cells: edge " + std::to_string(edge) +
                     " released: expected an exposed interior edge");
  if (released_[edge]) return;
  released_[edge] = 1;
  ++num_released_;
}

bool SurfaceCells::released_between(int a, int b) const {
  for (int e : mesh_->cell_edges(a)) {
    if (!released_[e]) continue;
    const MeshEdge& edge = mesh_->edge(e);
    if ((edge.cell0 == a ? edge.cell1 : edge.cell0) == b) return true;
  }
  return false;
}

bool SurfaceCells::has_exposed_edge(int cell) const {
  const auto flags = exposed_edges(cell);
  return std::any_of(flags.begin(), flags.end(), [](char f) { return f != 0; });
}

bool SurfaceCells::neighbours(int a, int b) const {
  // Compare the two loops directly: two contiguous reads beat walking the vertex-cell map, whose
  // lists are scattered through memory. Most candidate pairs of the search are neighbours, so
  // stop at the first shared vertex; each inner scan has no branch.
  const auto la = mesh_->cell_vertices(a);
  const auto lb = mesh_->cell_vertices(b);
  for (int v : la) {
    bool shared = false;
    for (int w : lb) shared |= v == w;
    if (shared) return num_released_ == 0 || !released_between(a, b);
  }
  return false;
}

void SurfaceCells::archive(StateArchive& a) {
  a.vector("surface.member", member_);
  a.vector("surface.cells", cells_);
  a.vector("surface.exposed", exposed_);
  a.vector("surface.released", released_);
  a.value("surface.num_released", num_released_);
}

}  // namespace vorodg
