#include "core/meshgen/PoissonDiskSampler.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <sstream>

#include "core/util/Errors.hpp"
#include "core/util/Random.hpp"

namespace vorodg {
namespace {

// Background grid of square cells of side d/sqrt(2): a cell's diagonal is d, so it holds at most
// one sample, and a cell that holds one is entirely covered by that sample's disk.
class SampleGrid {
 public:
  SampleGrid(const Rectangle& domain, double d) : domain_(domain), d_(d), d2_(d * d) {
    side_ = d / std::numbers::sqrt2;
    nx_ = std::max(1, static_cast<int>(std::ceil(domain.width() / side_)));
    ny_ = std::max(1, static_cast<int>(std::ceil(domain.height() / side_)));
    owner_.assign(static_cast<std::size_t>(nx_) * ny_, -1);
  }

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  double side() const { return side_; }
  int cell_count() const { return nx_ * ny_; }
  int owner(int cell) const { return owner_[cell]; }
  Point cell_origin(int cell) const {
    return domain_.lo() + side_ * Point(cell % nx_, cell / nx_);
  }
  int cell_of(const Point& p) const {
    const int i = std::clamp(static_cast<int>((p.x() - domain_.x0()) / side_), 0, nx_ - 1);
    const int j = std::clamp(static_cast<int>((p.y() - domain_.y0()) / side_), 0, ny_ - 1);
    return j * nx_ + i;
  }

  /// Calls f(sample index) for every sample in the 21 cells that can hold a sample closer than d
  /// to a point of `cell` (the 5x5 block without its corners).
  template <class F>
  bool any_neighbor(int cell, F&& f) const {
    const int ci = cell % nx_, cj = cell / nx_;
    for (int dj = -2; dj <= 2; ++dj) {
      const int j = cj + dj;
      if (j < 0 || j >= ny_) continue;
      for (int di = -2; di <= 2; ++di) {
        if (std::abs(di) == 2 && std::abs(dj) == 2) continue;
        const int i = ci + di;
        if (i < 0 || i >= nx_) continue;
        const int s = owner_[j * nx_ + i];
        if (s >= 0 && f(s)) return true;
      }
    }
    return false;
  }

  bool conflicts(const Point& p, const std::vector<Point>& samples) const {
    return any_neighbor(cell_of(p),
                        [&](int s) { return (samples[s] - p).squaredNorm() < d2_; });
  }
  /// True if one sample's disk contains the whole box [lo, hi] (disks are convex: the corners
  /// suffice).
  bool box_covered(int cell, const Point& lo, const Point& hi,
                   const std::vector<Point>& samples) const {
    return any_neighbor(cell, [&](int s) {
      const Point& c = samples[s];
      auto inside = [&](double x, double y) { return (Point(x, y) - c).squaredNorm() <= d2_; };
      return inside(lo.x(), lo.y()) && inside(hi.x(), lo.y()) && inside(lo.x(), hi.y()) &&
             inside(hi.x(), hi.y());
    });
  }
  void claim(int cell, int sample) { owner_[cell] = sample; }

 private:
  Rectangle domain_;
  double d_, d2_, side_ = 0.0;
  int nx_ = 1, ny_ = 1;
  std::vector<int> owner_;  // sample index per cell, -1 if empty
};

// A square still (possibly) uncovered: sub-square (a, b) of grid cell `cell` at the current
// refinement level (2^level sub-squares per side).
struct ActiveSquare {
  int cell;
  std::uint32_t a, b;
};

void check_options(const Rectangle& domain, double d) {
  if (!(d > 0.0) || !std::isfinite(d))
    throw InputError("minimum distance d = " + std::to_string(d) + ": expected a finite d > 0");
  if (d > domain.scale())
    throw InputError("minimum distance d = " + std::to_string(d) +
                     ": expected d no larger than the domain's longer side " +
                     std::to_string(domain.scale()));
  const double cells = domain.area() / (d * d);
  if (cells > 2e8)
    throw InputError("minimum distance d = " + std::to_string(d) + " gives about " +
                     std::to_string(static_cast<long long>(0.7 * cells)) +
                     " seeds, expected at most 1.4e8");
}

}  // namespace

PoissonDiskResult sample_poisson_disk(const Rectangle& domain, const PoissonDiskOptions& options) {
  const double d = options.min_distance;
  check_options(domain, d);
  SampleGrid grid(domain, d);
  Random rng(options.seed);
  PoissonDiskResult result;
  std::vector<Point>& samples = result.points;
  samples.reserve(static_cast<std::size_t>(0.75 * domain.area() / (d * d)) + 16);

  for (const Point& p : options.fixed_points) {
    const int cell = grid.cell_of(p);
    if (!domain.contains(p, 0.0) || grid.owner(cell) >= 0 || grid.conflicts(p, samples))
      throw InputError("fixed seed (" + std::to_string(p.x()) + "," + std::to_string(p.y()) +
                       ") is outside the domain or closer than d to another fixed seed");
    grid.claim(cell, static_cast<int>(samples.size()));
    samples.push_back(p);
  }

  std::vector<ActiveSquare> active;
  active.reserve(grid.cell_count());
  for (int c = 0; c < grid.cell_count(); ++c)
    if (grid.owner(c) < 0) active.push_back({c, 0, 0});

  double sub_side = grid.side();
  constexpr int kMaxLevel = 40;  // sub-squares of side d * 2^-40: below any useful resolution
  for (int level = 0; level <= kMaxLevel && !active.empty(); ++level) {
    // Dart throwing: every active square has the same size, so picking one uniformly and a point
    // uniformly inside it samples the uncovered area uniformly (unbiased sequential addition).
    const auto darts = static_cast<std::size_t>(options.darts_per_cell * active.size()) + 1;
    for (std::size_t t = 0; t < darts && !active.empty(); ++t) {
      const std::size_t k = rng.index(active.size());
      const ActiveSquare sq = active[k];
      ++result.darts_thrown;
      if (grid.owner(sq.cell) >= 0) {  // its grid cell got a sample: covered
        active[k] = active.back();
        active.pop_back();
        continue;
      }
      const Point origin = grid.cell_origin(sq.cell) + sub_side * Point(sq.a, sq.b);
      const Point p = origin + sub_side * Point(rng.uniform(), rng.uniform());
      if (!domain.contains(p, 0.0) || grid.conflicts(p, samples)) continue;
      grid.claim(grid.cell_of(p), static_cast<int>(samples.size()));
      samples.push_back(p);
      active[k] = active.back();
      active.pop_back();
    }
    // Refinement: split each remaining square in four and keep the children that still have an
    // uncovered part inside the domain.
    std::vector<ActiveSquare> children;
    children.reserve(active.size() * 2);
    const double half = 0.5 * sub_side;
    for (const ActiveSquare& sq : active) {
      if (grid.owner(sq.cell) >= 0) continue;
      const Point origin = grid.cell_origin(sq.cell) + sub_side * Point(sq.a, sq.b);
      for (std::uint32_t q = 0; q < 4; ++q) {
        const std::uint32_t qa = q & 1u, qb = q >> 1;
        Point lo = origin + half * Point(qa, qb);
        Point hi = lo + Point(half, half);
        lo = lo.cwiseMax(domain.lo());
        hi = hi.cwiseMin(domain.hi());
        if (!(lo.x() < hi.x() && lo.y() < hi.y())) continue;
        if (grid.box_covered(sq.cell, lo, hi, samples)) continue;
        children.push_back({sq.cell, 2 * sq.a + qa, 2 * sq.b + qb});
      }
    }
    active.swap(children);
    sub_side = half;
    result.refinement_passes = level + 1;
  }

  // Sampled points in grid (row-major) order: neighbouring seeds get nearby numbers.
  const auto n_fixed = static_cast<std::ptrdiff_t>(options.fixed_points.size());
  std::vector<std::pair<int, Point>> keyed;
  keyed.reserve(samples.size() - n_fixed);
  for (auto it = samples.begin() + n_fixed; it != samples.end(); ++it)
    keyed.emplace_back(grid.cell_of(*it), *it);
  std::sort(keyed.begin(), keyed.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  for (std::size_t i = 0; i < keyed.size(); ++i) samples[n_fixed + i] = keyed[i].second;
  return result;
}

std::vector<Point> sample_boundary_points(const Rectangle& domain, double d, std::uint64_t seed) {
  check_options(domain, d);
  Random rng(seed);
  std::vector<Point> points = {domain.lo(), Point(domain.x1(), domain.y0()), domain.hi(),
                               Point(domain.x0(), domain.y1())};
  // Counter-clockwise sides; on each, 1D random sequential addition between the corners.
  // Disjoint gaps fill independently, so a recursive fill has the distribution of the
  // sequential process.
  for (int s = 0; s < 4; ++s) {
    const Point a = points[s];
    const Point b = points[(s + 1) % 4];
    const double length = (b - a).norm();
    std::vector<double> ts;
    std::function<void(double, double)> fill = [&](double lo, double hi) {
      if (hi - lo < 2.0 * d) return;
      const double t = rng.uniform(lo + d, hi - d);
      ts.push_back(t);
      fill(lo, t);
      fill(t, hi);
    };
    fill(0.0, length);
    std::sort(ts.begin(), ts.end());
    for (double t : ts) points.push_back(a + (t / length) * (b - a));
  }
  return points;
}

double covered_fraction(std::size_t n_points, double d, double area) {
  return static_cast<double>(n_points) * std::numbers::pi * d * d / 4.0 / area;
}

}  // namespace vorodg
