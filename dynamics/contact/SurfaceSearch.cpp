#include "dynamics/contact/SurfaceSearch.hpp"

#include <string>

#include "core/io/StateArchive.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

/// The cell's bounding box. A non-finite vertex would slip through the box's min/max unnoticed,
/// so it is refused here, naming the cell.
Box box_of(std::span<const Point> loop, int cell) {
  Box box;
  for (const Point& p : loop) {
    if (!p.allFinite())
      throw NumericalError("surface contact: cell " + std::to_string(cell) +
                           " has a non-finite vertex position");
    box.extend(p);
  }
  return box;
}

}  // namespace

const std::vector<IndexPair>& SurfaceSearch::find(const SurfaceCells& surface,
                                                  std::span<const Point> position) {
  const PolygonMesh& mesh = surface.mesh();
  if (static_cast<int>(position.size()) != mesh.offsets().back())
    throw InputError("surface contact: " + std::to_string(position.size()) +
                     " positions: expected one per (cell, vertex) pair, " +
                     std::to_string(mesh.offsets().back()));
  const auto cells = surface.cells();
  boxes_.resize(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i)
    boxes_[i] = box_of(loop(mesh, position, cells[i]), cells[i]);
  surface_pairs_ = &candidates_.overlapping(surface, position, boxes_);
  cell_pairs_.clear();
  for (const IndexPair& ij : *surface_pairs_)
    cell_pairs_.push_back({cells[ij.first], cells[ij.second]});
  return cell_pairs_;
}

void SurfaceSearch::archive(StateArchive& a) {
  candidates_.archive(a);
  archive_boxes(a, "search.boxes", boxes_);
  a.vector("search.cell_pairs", cell_pairs_);
}

}  // namespace vorodg
