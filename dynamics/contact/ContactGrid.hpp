#pragma once
// The broad phase of contact: which axis-aligned boxes overlap, in O(N) per step. Each step
//   1. sets aside the large boxes, those with a side over kLargeBox x min_spacing;
//   2. sets the grid spacing s = max(min_spacing, largest side of the others) (times 1 + 1e-6,
//      so that round-off in the binning never hides a pair), so that no box in the grid is
//      wider than a grid cell;
//   3. bins every other box by the grid cell of its lower-left corner, with a counting sort;
//   4. looks for the partners of each binned box in the 3 x 3 grid cells around its own: a box
//      that overlaps it has its lower-left corner there, because no binned box is wider than s.
//      Each pair of neighbouring grid cells is searched from one side only (the half stencil:
//      own cell, right, and the three above), so each pair of boxes is tested once;
//   5. tests each large box against every box (a pair of large boxes from the smaller index).
// No tree and no comparison sort, so the cost is linear in the number of boxes plus the number
// of pairs, plus N per large box. Without step 1 one huge box among small ones would set s and
// put every box in a few grid cells: on a falling column at h = 4 the small-strain cells of
// spinning fragments swell to metres, and the search was a fifth of the run.
//
// The grid cells are numbered row by row over the bounding box of all boxes and folded modulo a
// bucket count of at most 4 N: while the boxes fill their bounding box this is the plain dense
// grid; when fragments fly apart and leave it mostly empty, grid cells far apart share a bucket
// (a spatial hash) and memory stays O(N). Sharing only adds candidates that the overlap test
// then rejects.
#include <Eigen/Geometry>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace vorodg {

class StateArchive;

using Box = Eigen::AlignedBox2d;

/// Saves or loads boxes as their corners (AlignedBox is not plain bytes by the type traits).
void archive_boxes(StateArchive& a, std::string_view name, std::vector<Box>& boxes);

/// Two boxes, by their index in the list given to ContactGrid::find, first < second.
struct IndexPair {
  int first = -1;
  int second = -1;
  bool operator==(const IndexPair&) const = default;
};

class ContactGrid {
 public:
  /// min_spacing > 0: the smallest grid spacing, e.g. the mesh's h_avg. Throws InputError.
  explicit ContactGrid(double min_spacing);

  /// Every pair of boxes that overlap (closed boxes: touching counts), each pair once with
  /// first < second. The order depends only on the boxes (binned pairs by the bucket of one of
  /// the two, then by index; the large boxes' pairs after them, by index), so it is the same on
  /// every run. Throws NumericalError naming a box that is empty or not finite. The result
  /// lives until the next call.
  const std::vector<IndexPair>& find(std::span<const Box> boxes);

  /// The spacing and bucket count the last call used.
  double spacing() const { return spacing_; }
  std::int64_t buckets() const { return num_buckets_; }

 public:
  /// Boxes with a side over this many min_spacing are tested against every box, not binned.
  static constexpr double kLargeBox = 4.0;

 private:
  /// Sorts the boxes into ordinary_ and large_, refusing bad ones.
  void classify(std::span<const Box> boxes);
  void set_up_grid(std::span<const Box> boxes);
  void bin(std::span<const Box> boxes);
  /// Step 5 of the header: the pairs of the large boxes.
  void collect_large(std::span<const Box> boxes);
  void collect();
  void collect_dense();
  void collect_folded();
  /// Tests sorted box s against the sorted boxes [from, to).
  void test_range(std::size_t s, int from, int to);
  std::int64_t grid_x(double x) const;
  std::int64_t grid_y(double y) const;
  std::int64_t bucket(std::int64_t ix, std::int64_t iy) const {
    const std::int64_t cell = iy * nx_ + ix;
    return cell < num_buckets_ ? cell : cell % num_buckets_;
  }

  double min_spacing_;
  double spacing_ = 0.0, inverse_spacing_ = 0.0;
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
  std::int64_t nx_ = 1, ny_ = 1, num_buckets_ = 1;
  std::vector<int> ordinary_, large_;     // box indices, increasing
  std::vector<char> is_large_;            // per box
  std::vector<std::int64_t> box_bucket_;  // per ordinary box
  std::vector<int> start_;                // bucket b holds order_[start_[b] .. start_[b+1])
  std::vector<int> next_;                 // the counting sort's cursors
  std::vector<int> order_;                // box indices, bucket by bucket, increasing within
  std::vector<Box> sorted_;               // the boxes in that order, for contiguous reads
  std::vector<IndexPair> pairs_;  // the first num_pairs_ are found; the rest is room to write
  std::size_t num_pairs_ = 0;
};

}  // namespace vorodg
