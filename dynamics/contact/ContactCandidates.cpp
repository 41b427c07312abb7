#include "dynamics/contact/ContactCandidates.hpp"

#include <algorithm>
#include <string>

#include "core/io/StateArchive.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {

ContactCandidates::ContactCandidates(double min_spacing)
    : grid_(min_spacing), skin_(kSkin * min_spacing) {}

bool ContactCandidates::stale(const SurfaceCells& surface, std::span<const Point> position) const {
  if (&surface != surface_ || surface.revision() != revision_ ||
      snapshot_.size() != position.size())
    return true;
  const PolygonMesh& mesh = surface.mesh();
  const double reach = skin_ * skin_;
  for (int c : surface.cells())
    for (int p = mesh.offsets()[c]; p < mesh.offsets()[c + 1]; ++p)
      if ((position[p] - snapshot_[p]).squaredNorm() > reach) return true;
  return false;
}

void ContactCandidates::rebuild(const SurfaceCells& surface, std::span<const Point> position,
                                std::span<const Box> boxes) {
  const PolygonMesh& mesh = surface.mesh();
  const auto cells = surface.cells();
  const Point grow = Point::Constant(skin_);
  inflated_.resize(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i)
    inflated_[i] = Box(boxes[i].min() - grow, boxes[i].max() + grow);
  candidates_.clear();
  for (const IndexPair& ij : grid_.find(inflated_))
    if (!surface.neighbours(cells[ij.first], cells[ij.second])) candidates_.push_back(ij);
  std::sort(candidates_.begin(), candidates_.end(), [](const IndexPair& a, const IndexPair& b) {
    return a.first != b.first ? a.first < b.first : a.second < b.second;
  });
  snapshot_.resize(position.size());
  for (int c : cells)
    for (int p = mesh.offsets()[c]; p < mesh.offsets()[c + 1]; ++p) snapshot_[p] = position[p];
  surface_ = &surface;
  revision_ = surface.revision();
  ++rebuilds_;
}

const std::vector<IndexPair>& ContactCandidates::overlapping(const SurfaceCells& surface,
                                                             std::span<const Point> position,
                                                             std::span<const Box> boxes) {
  if (static_cast<int>(boxes.size()) != surface.size())
    throw InputError("contact candidates: " + std::to_string(boxes.size()) +
                     " boxes: expected one per surface cell, " + std::to_string(surface.size()));
  ++calls_;
  if (stale(surface, position)) rebuild(surface, position, boxes);
  overlapping_.clear();
  for (const IndexPair& ij : candidates_)
    if (boxes[ij.first].intersects(boxes[ij.second])) overlapping_.push_back(ij);
  return overlapping_;
}

void ContactCandidates::archive(StateArchive& a) {
  a.value("candidates.revision", revision_);
  a.vector("candidates.snapshot", snapshot_);
  archive_boxes(a, "candidates.inflated", inflated_);
  a.vector("candidates.pairs", candidates_);
  a.vector("candidates.overlapping", overlapping_);
  a.value("candidates.rebuilds", rebuilds_);
  a.value("candidates.calls", calls_);
}

}  // namespace vorodg
