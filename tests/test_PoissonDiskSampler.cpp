// Maximal Poisson-disk sampling: minimum distance, maximality (no room left), containment,
// determinism, the saturated covered fraction of random sequential addition (~0.547), fixed
// points, input checks, independence of the thread count; and the 1D boundary sampler.
#include "core/meshgen/PoissonDiskSampler.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

// Bucket grid with cells of size >= r over a rectangle: neighbours within r of a point lie in
// the 3 x 3 block of buckets around it.
class PointGrid {
 public:
  PointGrid(const Rectangle& dom, double r, const std::vector<Point>& pts)
      : dom_(dom), cell_(r), pts_(pts) {
    nx_ = std::max(1, static_cast<int>(std::floor(dom.width() / r)));
    ny_ = std::max(1, static_cast<int>(std::floor(dom.height() / r)));
    cell_x_ = dom.width() / nx_;
    cell_y_ = dom.height() / ny_;
    buckets_.resize(static_cast<std::size_t>(nx_) * ny_);
    for (int i = 0; i < static_cast<int>(pts.size()); ++i) buckets_[bucket(pts[i])].push_back(i);
  }
  int ix(const Point& p) const {
    return std::clamp(static_cast<int>(std::floor((p.x() - dom_.x0()) / cell_x_)), 0, nx_ - 1);
  }
  int iy(const Point& p) const {
    return std::clamp(static_cast<int>(std::floor((p.y() - dom_.y0()) / cell_y_)), 0, ny_ - 1);
  }
  std::size_t bucket(const Point& p) const { return static_cast<std::size_t>(iy(p)) * nx_ + ix(p); }
  // Smallest distance from p to a point within one bucket ring (other than `skip`); +inf if none.
  double nearest(const Point& p, int skip = -1) const {
    double best = std::numeric_limits<double>::infinity();
    const int i0 = ix(p), j0 = iy(p);
    for (int j = std::max(0, j0 - 1); j <= std::min(ny_ - 1, j0 + 1); ++j)
      for (int i = std::max(0, i0 - 1); i <= std::min(nx_ - 1, i0 + 1); ++i)
        for (int k : buckets_[static_cast<std::size_t>(j) * nx_ + i])
          if (k != skip) best = std::min(best, (pts_[k] - p).norm());
    return best;
  }

 private:
  Rectangle dom_;
  double cell_;
  const std::vector<Point>& pts_;
  int nx_ = 1, ny_ = 1;
  double cell_x_ = 1, cell_y_ = 1;
  std::vector<std::vector<int>> buckets_;
};

PoissonDiskResult sample(const Rectangle& dom, double d, std::uint64_t seed) {
  PoissonDiskOptions o;
  o.min_distance = d;
  o.seed = seed;
  return sample_poisson_disk(dom, o);
}

// Minimum pairwise distance (through the grid; exact for distances below d).
double min_pair_distance(const Rectangle& dom, double d, const std::vector<Point>& pts) {
  const PointGrid grid(dom, d, pts);
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < static_cast<int>(pts.size()); ++i)
    best = std::min(best, grid.nearest(pts[i], i));
  return best;
}

// Largest distance from a probe of a grid with spacing d/8 to its nearest sample (capped at d:
// the grid only finds neighbours closer than d).
double max_probe_gap(const Rectangle& dom, double d, const std::vector<Point>& pts) {
  const PointGrid grid(dom, d, pts);
  const double step = d / 8;
  const int nx = static_cast<int>(std::ceil(dom.width() / step));
  const int ny = static_cast<int>(std::ceil(dom.height() / step));
  double worst = 0.0;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      const Point p(std::min(dom.x1(), dom.x0() + i * step),
                    std::min(dom.y1(), dom.y0() + j * step));
      worst = std::max(worst, std::min(d, grid.nearest(p)));
    }
  return worst;
}

TEST(PoissonDiskSampler, PointsAreAtLeastDApartAndInsideTheDomain) {
  const Rectangle dom(0, 0, 4, 1);
  const double d = 0.03;
  for (std::uint64_t seed : {1u, 2u, 12345u}) {
    const auto res = sample(dom, d, seed);
    ASSERT_GT(res.points.size(), 1000u);
    EXPECT_GE(min_pair_distance(dom, d, res.points), d * (1 - 1e-12)) << "seed " << seed;
    for (const Point& p : res.points) ASSERT_TRUE(dom.contains(p, 0.0)) << p.transpose();
  }
}

TEST(PoissonDiskSampler, SamplingIsMaximalNoRoomLeft) {
  // Every probe of a d/8 grid is within d of a sample: no further seed could be placed there.
  for (const Rectangle& dom : {Rectangle(0, 0, 4, 1), Rectangle(-1, 2, 0.5, 3.25)}) {
    const double d = 0.025;
    const auto res = sample(dom, d, 7);
    const double gap = max_probe_gap(dom, d, res.points);
    EXPECT_LT(gap, d * (1 + 1e-12))
        << "domain " << dom.to_string() << ": a probe is " << gap / d << " d from every sample";
  }
}

TEST(PoissonDiskSampler, SameSeedGivesIdenticalPointsDifferentSeedsDiffer) {
  const Rectangle dom(0, 0, 4, 1);
  const double d = 0.04;
  const auto a = sample(dom, d, 42);
  const auto b = sample(dom, d, 42);
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    ASSERT_EQ(a.points[i].x(), b.points[i].x()) << i;
    ASSERT_EQ(a.points[i].y(), b.points[i].y()) << i;
  }
  EXPECT_EQ(a.darts_thrown, b.darts_thrown);
  EXPECT_EQ(a.refinement_passes, b.refinement_passes);

  const auto c = sample(dom, d, 43);
  bool differ = a.points.size() != c.points.size();
  for (std::size_t i = 0; !differ && i < a.points.size(); ++i) differ = a.points[i] != c.points[i];
  EXPECT_TRUE(differ);
}

TEST(PoissonDiskSampler, SaturatedCoveredFractionIsThatOfRandomSequentialAddition) {
  // ~2e4 points on [0,4] x [0,1]: d = sqrt(0.7 area / N). Away from the sides (>= 3d) the packing
  // fraction of saturated RSA is ~0.547.
  const Rectangle dom(0, 0, 4, 1);
  const double d = std::sqrt(0.7 * dom.area() / 2e4);
  const auto res = sample(dom, d, 2024);
  const std::size_t n = res.points.size();
  ASSERT_GE(n, 10000u);
  const Rectangle inner(dom.x0() + 3 * d, dom.y0() + 3 * d, dom.x1() - 3 * d, dom.y1() - 3 * d);
  std::size_t n_inner = 0;
  for (const Point& p : res.points) n_inner += inner.contains(p, 0.0);
  ASSERT_GE(n_inner, 10000u);
  const double phi_inner = covered_fraction(n_inner, d, inner.area());
  EXPECT_GE(phi_inner, 0.53);
  EXPECT_LE(phi_inner, 0.56);
  const double phi = covered_fraction(n, d, dom.area());
  EXPECT_DOUBLE_EQ(phi, n * std::numbers::pi * d * d / 4 / dom.area());
  // Near the sides a seed's disk pokes out of the domain, so more seeds fit there.
  EXPECT_GT(phi, 0.5);
  EXPECT_LT(phi, 0.6);
  EXPECT_GT(res.refinement_passes, 0);
  EXPECT_GE(res.darts_thrown, n);
}

TEST(PoissonDiskSampler, CoveredFractionFormula) {
  EXPECT_DOUBLE_EQ(covered_fraction(100, 0.1, 1.0), 100 * std::numbers::pi * 0.01 / 4);
  EXPECT_EQ(covered_fraction(0, 0.1, 1.0), 0.0);
}

TEST(PoissonDiskSampler, FixedPointsComeFirstAndAreRespected) {
  const Rectangle dom(0, 0, 2, 1);
  const double d = 0.05;
  PoissonDiskOptions o;
  o.min_distance = d;
  o.seed = 5;
  o.fixed_points = {Point(0, 0), Point(2, 0), Point(2, 1), Point(0, 1), Point(1, 0.5), Point(1, 0)};
  const auto res = sample_poisson_disk(dom, o);
  ASSERT_GT(res.points.size(), o.fixed_points.size());
  for (std::size_t i = 0; i < o.fixed_points.size(); ++i)
    EXPECT_EQ(res.points[i], o.fixed_points[i]);
  EXPECT_GE(min_pair_distance(dom, d, res.points), d * (1 - 1e-12));
  EXPECT_LT(max_probe_gap(dom, d, res.points), d * (1 + 1e-12));
}

TEST(PoissonDiskSampler, RejectsBadMinimumDistance) {
  const Rectangle dom(0, 0, 4, 1);
  for (double d : {0.0, -0.1, std::numeric_limits<double>::infinity(),
                   std::numeric_limits<double>::quiet_NaN(), 4.5}) {
    SCOPED_TRACE(d);
    EXPECT_THROW(sample(dom, d, 1), InputError);
  }
  EXPECT_NO_THROW(sample(dom, 3.9, 1));
}

TEST(PoissonDiskSampler, ScalesLinearlyInTheNumberOfPoints) {
  // A coarse O(N) check: 4x the points should not cost much more than 4x the darts.
  const Rectangle dom(0, 0, 1, 1);
  const auto small = sample(dom, 0.02, 3);
  const auto large = sample(dom, 0.01, 3);
  const double ratio_points = double(large.points.size()) / small.points.size();
  const double ratio_darts = double(large.darts_thrown) / small.darts_thrown;
  EXPECT_NEAR(ratio_points, 4.0, 0.4);
  EXPECT_LT(ratio_darts, 2 * ratio_points);
}

TEST(PoissonDiskSampler, BoundaryPointsIncludeCornersAndAreSpacedBetweenDAnd2D) {
  const Rectangle dom(-1, 0, 3, 1);
  const double d = 0.07;
  const auto pts = sample_boundary_points(dom, d, 11);
  const double tol = 1e-12 * dom.scale();
  for (const Point& corner :
       {dom.lo(), Point(dom.x1(), dom.y0()), dom.hi(), Point(dom.x0(), dom.y1())}) {
    const auto n = std::count(pts.begin(), pts.end(), corner);
    EXPECT_EQ(n, 1) << "corner " << corner.transpose();
  }
  for (const Point& p : pts) {
    const auto near = dom.sides_near(p, tol);
    EXPECT_TRUE(near[0] || near[1] || near[2] || near[3]) << "not on a side: " << p.transpose();
    EXPECT_TRUE(dom.contains(p, 0.0));
  }
  for (Side s : {Side::left, Side::right, Side::bottom, Side::top}) {
    const bool vertical = s == Side::left || s == Side::right;
    std::vector<double> t;
    for (const Point& p : pts)
      if (dom.distance_to_side(p, s) == 0.0) t.push_back(vertical ? p.y() : p.x());
    std::sort(t.begin(), t.end());
    ASSERT_GE(t.size(), 2u) << side_name(s);
    EXPECT_EQ(t.front(), vertical ? dom.y0() : dom.x0()) << side_name(s);
    EXPECT_EQ(t.back(), vertical ? dom.y1() : dom.x1()) << side_name(s);
    for (std::size_t i = 1; i < t.size(); ++i) {
      const double gap = t[i] - t[i - 1];
      EXPECT_GE(gap, d * (1 - 1e-12)) << side_name(s) << " gap " << i;
      EXPECT_LE(gap, 2 * d * (1 + 1e-12)) << side_name(s) << " gap " << i;
    }
  }
  // Deterministic.
  EXPECT_EQ(pts, sample_boundary_points(dom, d, 11));
}

// The random numbers are drawn in one sequence and the arrivals resolve to a unique set, so the
// samples are the same to the bit on any number of threads (with and without fixed points).
TEST(PoissonDisk, ThreadsDoNotChangeTheSamples) {
  const Rectangle dom(0.0, -0.5, 4.0, 0.5);
  for (const double d : {0.05, 0.013})
    for (const std::uint64_t seed : {3u, 17u})
      for (const bool fixed : {false, true}) {
        PoissonDiskOptions o;
        o.min_distance = d;
        o.seed = seed;
        if (fixed) o.fixed_points = {Point(0.0, -0.5), Point(2.0, 0.0), Point(4.0, 0.5)};
        const auto one = sample_poisson_disk(dom, o);
        o.threads = 2;
        const auto two = sample_poisson_disk(dom, o);
        EXPECT_EQ(one.points, two.points) << "d " << d << " seed " << seed;
        EXPECT_EQ(one.darts_thrown, two.darts_thrown);
        EXPECT_EQ(one.refinement_passes, two.refinement_passes);
      }
}

}  // namespace
}  // namespace vorodg
