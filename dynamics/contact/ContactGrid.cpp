#include "dynamics/contact/ContactGrid.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/io/StateArchive.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

// Grid indices stay below 2^24 per axis: products and row numbers fit easily in 64 bits, and the
// relative round-off of the binning (~2^24 x 1e-16) stays far below the 1e-6 slack of s.
constexpr double kMaxCellsPerAxis = 16777216.0;
constexpr double kSlack = 1.0 + 1e-6;
constexpr std::int64_t kBucketsPerBox = 4;

void check_box(const Box& b, std::size_t i) {
  const bool finite = b.min().allFinite() && b.max().allFinite();
  if (!finite || b.isEmpty())
    throw NumericalError("contact grid: box " + std::to_string(i) +
                         (finite ? " is empty (min > max)" : " is not finite") +
                         ": a cell has degenerate or non-finite vertex positions");
}

}  // namespace

ContactGrid::ContactGrid(double min_spacing) : min_spacing_(min_spacing) {
  require_parameter(std::isfinite(min_spacing) && min_spacing > 0.0, "contact grid spacing",
                    min_spacing, "> 0");
}

const std::vector<IndexPair>& ContactGrid::find(std::span<const Box> boxes) {
  pairs_.clear();
  num_pairs_ = 0;
  if (boxes.size() < 2) return pairs_;
  classify(boxes);
  set_up_grid(boxes);
  bin(boxes);
  collect();
  collect_large(boxes);
  pairs_.resize(num_pairs_);
  return pairs_;
}

void ContactGrid::classify(std::span<const Box> boxes) {
  ordinary_.clear();
  large_.clear();
  is_large_.assign(boxes.size(), 0);
  const double limit = kLargeBox * min_spacing_;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    check_box(boxes[i], i);
    is_large_[i] = boxes[i].sizes().maxCoeff() > limit;
    (is_large_[i] ? large_ : ordinary_).push_back(static_cast<int>(i));
  }
}

void ContactGrid::set_up_grid(std::span<const Box> boxes) {
  Box all;
  double largest = 0.0;
  for (int i : ordinary_) {
    all.extend(boxes[i]);
    largest = std::max(largest, boxes[i].sizes().maxCoeff());
  }
  if (ordinary_.empty()) all.extend(Eigen::Vector2d::Zero());
  const Eigen::Vector2d span = all.sizes();
  spacing_ = std::max({min_spacing_, largest, span.maxCoeff() / kMaxCellsPerAxis}) * kSlack;
  inverse_spacing_ = 1.0 / spacing_;
  origin_ = all.min();
  nx_ = static_cast<std::int64_t>(span.x() * inverse_spacing_) + 1;
  ny_ = static_cast<std::int64_t>(span.y() * inverse_spacing_) + 1;
  const auto n = std::max<std::int64_t>(static_cast<std::int64_t>(ordinary_.size()), 1);
  // nx * ny < 2^50 by the cap above, so the product cannot overflow.
  num_buckets_ = std::min(nx_ * ny_, kBucketsPerBox * n);
}

// Binning and look-up use these same two functions, so a box is always found in its bucket.
std::int64_t ContactGrid::grid_x(double x) const {
  return std::min(static_cast<std::int64_t>((x - origin_.x()) * inverse_spacing_), nx_ - 1);
}

std::int64_t ContactGrid::grid_y(double y) const {
  return std::min(static_cast<std::int64_t>((y - origin_.y()) * inverse_spacing_), ny_ - 1);
}

void ContactGrid::bin(std::span<const Box> boxes) {
  const std::size_t n = ordinary_.size();
  box_bucket_.resize(n);
  start_.assign(num_buckets_ + 1, 0);
  for (std::size_t k = 0; k < n; ++k) {
    const Box& b = boxes[ordinary_[k]];
    box_bucket_[k] = bucket(grid_x(b.min().x()), grid_y(b.min().y()));
    ++start_[box_bucket_[k] + 1];
  }
  for (std::int64_t b = 0; b < num_buckets_; ++b) start_[b + 1] += start_[b];
  // Counting sort, stable: within a bucket the boxes stay in increasing index.
  order_.resize(n);
  sorted_.resize(n);
  next_.assign(start_.begin(), start_.end() - 1);
  for (std::size_t k = 0; k < n; ++k) {
    const int slot = next_[box_bucket_[k]]++;
    order_[slot] = ordinary_[k];
    sorted_[slot] = boxes[ordinary_[k]];
  }
}

void ContactGrid::collect_large(std::span<const Box> boxes) {
  for (int i : large_)
    for (int j = 0; j < static_cast<int>(boxes.size()); ++j) {
      if (j == i || (is_large_[j] && j < i) || !boxes[i].intersects(boxes[j])) continue;
      if (pairs_.size() == num_pairs_) pairs_.resize(2 * num_pairs_ + 16);
      pairs_[num_pairs_++] = i < j ? IndexPair{i, j} : IndexPair{j, i};
    }
}

void ContactGrid::collect() {
  if (num_buckets_ == nx_ * ny_)
    collect_dense();
  else
    collect_folded();
}

void ContactGrid::test_range(std::size_t s, int from, int to) {
  if (from >= to) return;
  // Branch-free: about one test in seven hits, so a branch per test would mispredict often.
  // Every candidate is written to the next free slot, and the count advances only on a hit.
  const std::size_t needed = num_pairs_ + static_cast<std::size_t>(to - from);
  if (pairs_.size() < needed) pairs_.resize(std::max(needed, 2 * pairs_.size()));
  const int i = order_[s];
  const Box& bi = sorted_[s];
  IndexPair* out = pairs_.data() + num_pairs_;
  std::size_t hits = 0;
  for (int t = from; t < to; ++t) {
    const Box& bt = sorted_[t];
    const bool hit = (bi.min().x() <= bt.max().x()) & (bt.min().x() <= bi.max().x()) &
                     (bi.min().y() <= bt.max().y()) & (bt.min().y() <= bi.max().y());
    const int j = order_[t];
    out[hits] = i < j ? IndexPair{i, j} : IndexPair{j, i};
    hits += hit;
  }
  num_pairs_ += hits;
}

void ContactGrid::collect_dense() {
  // Half the stencil: each box meets the boxes after it in its own bucket and in the bucket to
  // its right, and those in the three buckets of the row above; every other neighbouring box
  // meets it from its own side. Buckets are numbered row by row, so each part is one contiguous
  // run of the sorted boxes. Boxes are visited bucket by bucket, so that consecutive boxes read
  // the same memory.
  for (std::size_t s = 0; s < order_.size(); ++s) {
    const Box& bi = sorted_[s];
    const std::int64_t ix = grid_x(bi.min().x()), iy = grid_y(bi.min().y());
    const std::int64_t b = iy * nx_ + ix;
    const std::int64_t right = ix + 1 < nx_ ? b + 2 : b + 1;
    test_range(s, static_cast<int>(s) + 1, start_[right]);
    if (iy + 1 < ny_) {
      const std::int64_t first = b + nx_ - (ix > 0 ? 1 : 0);
      const std::int64_t last = b + nx_ + (ix + 1 < nx_ ? 2 : 1);
      test_range(s, start_[first], start_[last]);
    }
  }
}

void ContactGrid::collect_folded() {
  // The whole 3 x 3 stencil, each pair taken from its smaller index only: with folding, a
  // bucket can stand for a grid cell on either side, so "the half ahead" is not well defined.
  for (std::size_t s = 0; s < order_.size(); ++s) {
    const int i = order_[s];
    const Box& bi = sorted_[s];
    const std::int64_t ix = grid_x(bi.min().x()), iy = grid_y(bi.min().y());
    std::int64_t seen[9];
    int num_seen = 0;
    for (std::int64_t y = std::max<std::int64_t>(iy - 1, 0); y <= std::min(iy + 1, ny_ - 1); ++y)
      for (std::int64_t x = std::max<std::int64_t>(ix - 1, 0); x <= std::min(ix + 1, nx_ - 1);
           ++x) {
        const std::int64_t b = bucket(x, y);
        // Two of the nine cells may share a bucket: visit it once.
        if (std::find(seen, seen + num_seen, b) != seen + num_seen) continue;
        seen[num_seen++] = b;
        for (int t = start_[b]; t < start_[b + 1]; ++t) {
          const int j = order_[t];
          if (j > i && bi.intersects(sorted_[t])) {
            if (pairs_.size() == num_pairs_) pairs_.resize(2 * num_pairs_ + 16);
            pairs_[num_pairs_++] = {i, j};
          }
        }
      }
  }
}

void archive_boxes(StateArchive& a, std::string_view name, std::vector<Box>& boxes) {
  std::vector<Eigen::Vector2d> corners;
  for (const Box& b : boxes) corners.push_back(b.min()), corners.push_back(b.max());
  a.vector(name, corners);
  if (!a.loading()) return;
  boxes.resize(corners.size() / 2);
  for (std::size_t i = 0; i < boxes.size(); ++i) boxes[i] = Box(corners[2 * i], corners[2 * i + 1]);
}

}  // namespace vorodg
