// The grid search of contact: the same overlapping pairs as the O(N^2) brute force on random
// polygon sets (two rcp bodies moved onto each other, random boxes, a few huge boxes among small
// ones, boxes flung far apart so that the grid folds), each pair once, first < second, in the
// same order on every run.
#include "dynamics/contact/ContactGrid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>
#include <vector>

#include "core/util/Errors.hpp"
#include "core/util/Random.hpp"
#include "support/ContactScenes.hpp"

namespace vorodg {
namespace {

using PairSet = std::set<std::pair<int, int>>;

PairSet brute_force(const std::vector<Box>& boxes) {
  PairSet out;
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j)
      if (boxes[i].intersects(boxes[j])) out.insert({int(i), int(j)});
  return out;
}

/// The grid's pairs as a set, after checking each comes once with first < second.
PairSet checked_set(const std::vector<IndexPair>& pairs) {
  PairSet out;
  for (const IndexPair& p : pairs) {
    EXPECT_LT(p.first, p.second);
    EXPECT_TRUE(out.insert({p.first, p.second}).second) << p.first << ", " << p.second;
  }
  return out;
}

std::vector<Box> cell_boxes(const testing::TwoBodies& scene) {
  std::vector<Box> boxes;
  for (int c = 0; c < scene.mesh.num_cells(); ++c) {
    Box b;
    for (int p = scene.mesh.offsets()[c]; p < scene.mesh.offsets()[c + 1]; ++p)
      b.extend(scene.x[p]);
    boxes.push_back(b);
  }
  return boxes;
}

TEST(ContactGrid, MatchesBruteForceOnOverlappingRcpBodies) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const double d = 0.05;
    const auto scene = testing::two_bodies(d, seed, Point(0.8, 0.6), 0.3 * double(seed), 0.3);
    const auto boxes = cell_boxes(scene);
    ContactGrid grid(scene.mesh.h_avg());
    const PairSet expected = brute_force(boxes);
    EXPECT_EQ(checked_set(grid.find(boxes)), expected) << "seed " << seed;
    EXPECT_GT(expected.size(), boxes.size());  // the bodies overlap: many pairs
    EXPECT_GE(grid.spacing(), scene.mesh.h_avg());
  }
}

TEST(ContactGrid, MatchesBruteForceOnRandomBoxesOfMixedSizes) {
  Random random(11);
  for (int trial = 0; trial < 5; ++trial) {
    std::vector<Box> boxes;
    for (int i = 0; i < 3000; ++i) {
      const Point lo(random.uniform(0.0, 2.0), random.uniform(0.0, 1.0));
      const Point size(random.uniform(0.0, 0.04), random.uniform(0.0, 0.04));
      boxes.emplace_back(lo, lo + size);
    }
    ContactGrid grid(0.01);  // smaller than the boxes: the largest box sets the spacing
    EXPECT_EQ(checked_set(grid.find(boxes)), brute_force(boxes)) << "trial " << trial;
    EXPECT_GE(grid.spacing(), 0.04 * 0.99);
  }
}

TEST(ContactGrid, LargeBoxesAreTestedAsideAndLeaveTheSpacingAlone) {
  // 2000 small boxes and 20 boxes up to a hundred times larger (swollen cells): the grid keeps
  // the small ones' spacing, and the pairs are still exactly the brute force's.
  Random random(14);
  std::vector<Box> boxes;
  for (int i = 0; i < 2020; ++i) {
    const Point lo(random.uniform(0.0, 2.0), random.uniform(0.0, 1.0));
    const double side = i % 101 == 0 ? random.uniform(0.1, 1.0) : random.uniform(0.0, 0.02);
    boxes.emplace_back(lo, lo + Point(side, random.uniform(0.5, 1.0) * side));
  }
  ContactGrid grid(0.01);
  EXPECT_EQ(checked_set(grid.find(boxes)), brute_force(boxes));
  EXPECT_LE(grid.spacing(), ContactGrid::kLargeBox * 0.01 * (1 + 1e-6));
  std::vector<Box> large_only(boxes.begin(), boxes.begin() + 1);
  large_only.push_back(Box(Point(0.5, 0.5), Point(1.5, 1.5)));
  EXPECT_EQ(checked_set(grid.find(large_only)), brute_force(large_only));
}

TEST(ContactGrid, FoldedGridOfScatteredFragmentsMatchesBruteForce) {
  // Clusters of boxes a million spacings apart: the dense grid would need ~1e12 cells; folded,
  // it keeps at most 4 buckets per box.
  Random random(12);
  std::vector<Box> boxes;
  for (int cluster = 0; cluster < 20; ++cluster) {
    const Point centre(random.uniform(-1e4, 1e4), random.uniform(-1e4, 1e4));
    for (int i = 0; i < 100; ++i) {
      const Point lo = centre + Point(random.uniform(0.0, 0.3), random.uniform(0.0, 0.3));
      boxes.emplace_back(lo, lo + Point(random.uniform(0.0, 0.02), random.uniform(0.0, 0.02)));
    }
  }
  ContactGrid grid(0.01);
  EXPECT_EQ(checked_set(grid.find(boxes)), brute_force(boxes));
  EXPECT_LE(grid.buckets(), 4 * static_cast<std::int64_t>(boxes.size()));
}

TEST(ContactGrid, SameOrderOnEveryRun) {
  const auto scene = testing::two_bodies(0.05, 5, Point(1.0, 0.5), 1.0, 0.2);
  const auto boxes = cell_boxes(scene);
  ContactGrid one(scene.mesh.h_avg()), two(scene.mesh.h_avg());
  const std::vector<IndexPair> first = one.find(boxes);
  EXPECT_EQ(one.find(boxes), first);  // the same object again
  EXPECT_EQ(two.find(boxes), first);  // a fresh one
}

TEST(ContactGrid, TouchingCountsAndDegenerateInputs) {
  ContactGrid grid(1.0);
  EXPECT_TRUE(grid.find(std::vector<Box>{}).empty());
  EXPECT_TRUE(grid.find(std::vector<Box>{Box(Point(0, 0), Point(1, 1))}).empty());
  // Closed boxes: sharing an edge or a corner is overlap; a gap of one ulp is not.
  const std::vector<Box> touching{Box(Point(0, 0), Point(1, 1)), Box(Point(1, 0), Point(2, 1)),
                                  Box(Point(2, 1), Point(3, 2)),
                                  Box(Point(std::nextafter(3.0, 4.0), 0), Point(4, 1))};
  const PairSet expected{{0, 1}, {1, 2}};
  EXPECT_EQ(checked_set(grid.find(touching)), expected);
  // Many copies of one box, and points (zero-size boxes): all pairs.
  const std::vector<Box> same(50, Box(Point(0.5, 0.5), Point(0.5, 0.5)));
  EXPECT_EQ(grid.find(same).size(), 50u * 49u / 2u);
}

TEST(ContactGrid, RefusesNonFiniteOrEmptyBoxesAndBadSpacing) {
  ContactGrid grid(1.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(
      grid.find(std::vector<Box>{Box(Point(0, 0), Point(1, 1)), Box(Point(nan, 0), Point(1, 1))}),
      NumericalError);
  EXPECT_THROW(grid.find(std::vector<Box>{Box(Point(0, 0), Point(1, 1)), Box()}), NumericalError);
  EXPECT_THROW(ContactGrid{0.0}, InputError);
  EXPECT_THROW(ContactGrid{nan}, InputError);
}

}  // namespace
}  // namespace vorodg
