#include "core/meshgen/PoissonDiskSampler.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <sstream>

#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "core/util/Random.hpp"

namespace vorodg {
namespace {

// Background grid of square cells of side d/sqrt(2): a cell's diagonal is d, so it holds at most
// one sample, and a cell that holds one is entirely covered by that sample's disk. Samples are
// stored in their cell (NaN marks an empty cell): the neighbourhood tests, which dominate the
// cost, then read a few contiguous rows instead of chasing indices.
class SampleGrid {
 public:
  SampleGrid(const Rectangle& domain, double d) : domain_(domain), d2_(d * d) {
    side_ = d / std::numbers::sqrt2;
    nx_ = std::max(1, static_cast<int>(std::ceil(domain.width() / side_)));
    ny_ = std::max(1, static_cast<int>(std::ceil(domain.height() / side_)));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    cells_.assign(static_cast<std::size_t>(nx_) * ny_, Point(nan, nan));
  }

  int cell_count() const { return nx_ * ny_; }
  double side() const { return side_; }
  bool occupied(int cell) const { return !std::isnan(cells_[cell].x()); }
  const Point& sample(int cell) const { return cells_[cell]; }
  Point cell_origin(int cell) const { return domain_.lo() + side_ * Point(cell % nx_, cell / nx_); }
  int cell_of(const Point& p) const {
    const int i = std::clamp(static_cast<int>((p.x() - domain_.x0()) / side_), 0, nx_ - 1);
    const int j = std::clamp(static_cast<int>((p.y() - domain_.y0()) / side_), 0, ny_ - 1);
    return j * nx_ + i;
  }

  /// True if f(sample) holds for a sample in one of the 21 cells that can hold a sample closer
  /// than d to a point of `cell` (the 5x5 block without its corners). Empty cells hold NaN,
  /// for which every distance comparison is false, so they need no test of their own.
  template <class F>
  bool any_neighbor(int cell, F&& f) const {
    return for_each_neighbor_cell(cell, [&](int k) { return f(cells_[k]); });
  }

  /// Calls f(cell index) for the 21 neighbour cells of `cell` (including itself) until f
  /// returns true.
  template <class F>
  bool for_each_neighbor_cell(int cell, F&& f) const {
    const int ci = cell % nx_, cj = cell / nx_;
    const int j0 = std::max(cj - 2, 0), j1 = std::min(cj + 2, ny_ - 1);
    for (int j = j0; j <= j1; ++j) {
      const int reach = (j == cj - 2 || j == cj + 2) ? 1 : 2;
      const int i0 = std::max(ci - reach, 0), i1 = std::min(ci + reach, nx_ - 1);
      for (int i = i0; i <= i1; ++i)
        if (f(j * nx_ + i)) return true;
    }
    return false;
  }
  double d2() const { return d2_; }

  bool conflicts(const Point& p) const {
    return any_neighbor(cell_of(p), [&](const Point& s) { return (s - p).squaredNorm() < d2_; });
  }
  /// The samples that can cover part of `cell` (at most 21).
  int gather_neighbors(int cell, std::array<Point, 21>& out) const {
    int n = 0;
    any_neighbor(cell, [&](const Point& s) {
      if (!std::isnan(s.x())) out[n++] = s;
      return false;
    });
    return n;
  }
  void place(const Point& p) { cells_[cell_of(p)] = p; }

 private:
  Rectangle domain_;
  double d2_, side_ = 0.0;
  int nx_ = 1, ny_ = 1;
  std::vector<Point> cells_;
};

// A square still (possibly) uncovered: sub-square (a, b) of grid cell `cell` at the current
// refinement level (2^level sub-squares per side).
struct ActiveSquare {
  int cell;
  std::uint32_t a, b;
};

/// True if one of the disks of radius sqrt(d2) around `centres` contains the whole box [lo, hi]
/// (disks are convex: the corners suffice).
bool box_covered(const Point& lo, const Point& hi, const Point* centres, int n, double d2) {
  for (int k = 0; k < n; ++k) {
    const Point& c = centres[k];
    auto inside = [&](double x, double y) { return (Point(x, y) - c).squaredNorm() <= d2; };
    if (inside(lo.x(), lo.y()) && inside(hi.x(), lo.y()) && inside(lo.x(), hi.y()) &&
        inside(hi.x(), hi.y()))
      return true;
  }
  return false;
}

struct Dart {
  int cell;
  Point p;
  std::uint64_t arrival;  // random arrival time: the order of sequential addition
};

bool arrives_before(const Dart& a, std::size_t ia, const Dart& b, std::size_t ib) {
  return a.arrival < b.arrival || (a.arrival == b.arrival && ia < ib);
}

/// Accepts exactly the darts that sequential addition in arrival order would accept: a dart is
/// accepted iff no earlier-arriving accepted dart lies closer than d. This is the greedy
/// independent set by priority, found by sweeping the darts in grid order until every dart is
/// decided (accepted once all earlier conflicting darts are rejected, rejected once one of them
/// is accepted) — the same answer as processing arrivals one by one, with memory access in grid
/// order instead of random order.
enum : char { undecided, accepted, rejected };

std::vector<std::atomic<char>> resolve_arrivals(const std::vector<Dart>& darts,
                                                const SampleGrid& grid,
                                                std::vector<int>& first_dart, double d2,
                                                int threads) {
  // Darts decided in the same sweep by other threads may or may not be seen: every decision is
  // still right (accepted once all earlier conflicting darts are rejected, rejected once one is
  // accepted), and the set they converge to is unique, so the answer does not depend on threads.
  std::vector<std::atomic<char>> status(darts.size());
  for (auto& s : status) s.store(undecided, std::memory_order_relaxed);
  for (std::size_t i = darts.size(); i-- > 0;) first_dart[darts[i].cell] = static_cast<int>(i);
  const long n = static_cast<long>(darts.size());
  long open = n;
  while (open > 0) {
    long decided = 0;
#pragma omp parallel for schedule(static, 4096) reduction(+ : decided) num_threads(threads)
    for (long i = 0; i < n; ++i) {
      if (status[i].load(std::memory_order_relaxed) != undecided) continue;
      bool blocked = false, beaten = false;
      grid.for_each_neighbor_cell(darts[i].cell, [&](int cell) {
        for (long j = first_dart[cell]; j >= 0 && j < n && darts[j].cell == cell && !beaten; ++j) {
          const char sj = status[j].load(std::memory_order_relaxed);
          if (j == i || sj == rejected) continue;
          if (!arrives_before(darts[j], j, darts[i], i)) continue;
          if ((darts[j].p - darts[i].p).squaredNorm() >= d2) continue;
          if (sj == accepted)
            beaten = true;
          else
            blocked = true;
        }
        return beaten;
      });
      if (beaten || !blocked) {
        status[i].store(beaten ? rejected : accepted, std::memory_order_relaxed);
        ++decided;
      }
    }
    open -= decided;
  }
  for (const Dart& dart : darts) first_dart[dart.cell] = -1;
  return status;
}

/// One pass of arrivals: every active square receives a Poisson number of darts (mean
/// `darts_per_square`) at uniform positions and random arrival times. All squares of a pass have
/// the same size, so the arrivals are uniform over the uncovered area: unbiased sequential
/// addition. Darts are generated square by square (the squares are in grid order).
void throw_darts(SampleGrid& grid, const std::vector<ActiveSquare>& active, double sub_side,
                 const Rectangle& domain, double darts_per_square, Random& rng,
                 std::vector<int>& first_dart, int threads, PoissonDiskResult& result) {
  std::vector<Dart> darts;
  darts.reserve(active.size());
  const double exp_minus_mean = std::exp(-darts_per_square);
  const bool test_at_once = threads <= 1;  // one thread: test each dart while it is in cache
  for (const ActiveSquare& sq : active) {  // the random numbers, in one sequence
    const int n = rng.poisson(exp_minus_mean);
    const Point origin = grid.cell_origin(sq.cell) + sub_side * Point(sq.a, sq.b);
    for (int k = 0; k < n; ++k) {
      const Point p = origin + sub_side * Point(rng.uniform(), rng.uniform());
      const std::uint64_t arrival = rng.bits();
      ++result.darts_thrown;
      if (!domain.contains(p, 0.0) || grid.occupied(sq.cell)) continue;
      if (test_at_once && grid.conflicts(p)) continue;
      darts.push_back({sq.cell, p, arrival});
    }
  }
  if (!test_at_once) {
    // The grid does not change while the darts are tested against it: in parallel, then the
    // darts that conflict with a sample are dropped in place, the others kept in order.
    std::vector<char> conflicting(darts.size());
#pragma omp parallel for schedule(static, 4096) num_threads(threads)
    for (long i = 0; i < static_cast<long>(darts.size()); ++i)
      conflicting[i] = grid.conflicts(darts[i].p);
    std::size_t kept = 0;
    for (std::size_t i = 0; i < darts.size(); ++i)
      if (!conflicting[i]) darts[kept++] = darts[i];
    darts.resize(kept);
  }
  const auto status = resolve_arrivals(darts, grid, first_dart, grid.d2(), threads);
  for (std::size_t i = 0; i < darts.size(); ++i)
    if (status[i].load(std::memory_order_relaxed) == accepted) grid.place(darts[i].p);
}

/// The children of one square that still have an uncovered part inside the domain.
void add_uncovered_children(const SampleGrid& grid, const ActiveSquare& sq, double side,
                            const Rectangle& domain, std::vector<ActiveSquare>& children) {
  if (grid.occupied(sq.cell)) return;
  std::array<Point, 21> near;
  const int n_near = grid.gather_neighbors(sq.cell, near);
  const Point origin = grid.cell_origin(sq.cell) + side * Point(sq.a, sq.b);
  const double half = 0.5 * side;
  for (std::uint32_t q = 0; q < 4; ++q) {
    const std::uint32_t qa = q & 1u, qb = q >> 1;
    Point lo = origin + half * Point(qa, qb);
    Point hi = lo + Point(half, half);
    lo = lo.cwiseMax(domain.lo());
    hi = hi.cwiseMin(domain.hi());
    if (!(lo.x() < hi.x() && lo.y() < hi.y())) continue;
    if (box_covered(lo, hi, near.data(), n_near, grid.d2())) continue;
    children.push_back({sq.cell, 2 * sq.a + qa, 2 * sq.b + qb});
  }
}

/// Refinement: each remaining square split in four, the children kept in the squares' order
/// (chunks of squares refined in parallel, then joined in order).
std::vector<ActiveSquare> refine(const SampleGrid& grid, const std::vector<ActiveSquare>& active,
                                 double side, const Rectangle& domain, int threads) {
  const long n = static_cast<long>(active.size());
  const long chunk = threads > 1 ? 16384 : std::max(n, 1L);  // one thread: one part, no joining
  std::vector<std::vector<ActiveSquare>> parts((n + chunk - 1) / chunk);
  if (parts.size() == 1) parts[0].reserve(active.size() * 2);
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (long part = 0; part < static_cast<long>(parts.size()); ++part)
    for (long i = part * chunk; i < std::min(n, (part + 1) * chunk); ++i)
      add_uncovered_children(grid, active[i], side, domain, parts[part]);
  if (parts.size() == 1) return std::move(parts[0]);
  std::vector<ActiveSquare> children;
  children.reserve(active.size() * 2);
  for (const auto& part : parts) children.insert(children.end(), part.begin(), part.end());
  return children;
}

void check_sampler_options(const Rectangle& domain, double d) {
  if (!(d > 0.0) || !std::isfinite(d))
    throw InputError("minimum distance d = " + fmt(d) + ": expected a finite d > 0");
  if (d > domain.scale())
    throw InputError("minimum distance d = " + fmt(d) +
                     ": expected d no larger than the domain's longer side " + fmt(domain.scale()));
  const double cells = domain.area() / (d * d);
  if (cells > 2e8)
    throw InputError("minimum distance d = " + fmt(d) + " gives about " +
                     std::to_string(static_cast<long long>(0.7 * cells)) +
                     " seeds, expected at most 1.4e8");
}

}  // namespace

PoissonDiskResult sample_poisson_disk(const Rectangle& domain, const PoissonDiskOptions& options) {
  const double d = options.min_distance;
  check_sampler_options(domain, d);
  SampleGrid grid(domain, d);
  Random rng(options.seed);
  PoissonDiskResult result;
  std::vector<Point>& samples = result.points;
  samples.reserve(static_cast<std::size_t>(0.75 * domain.area() / (d * d)) + 16);

  std::vector<char> fixed_cell(options.fixed_points.empty() ? 0 : grid.cell_count(), 0);
  for (const Point& p : options.fixed_points) {
    const int cell = grid.cell_of(p);
    if (!domain.contains(p, 0.0) || grid.occupied(cell) || grid.conflicts(p))
      throw InputError("fixed seed (" + fmt(p.x()) + "," + fmt(p.y()) +
                       ") is outside the domain or closer than d to another fixed seed");
    grid.place(p);
    fixed_cell[cell] = 1;
    samples.push_back(p);
  }

  std::vector<ActiveSquare> active;
  active.reserve(grid.cell_count());
  for (int c = 0; c < grid.cell_count(); ++c)
    if (!grid.occupied(c)) active.push_back({c, 0, 0});

  std::vector<int> first_dart(grid.cell_count(), -1);  // per cell, its first dart of a pass
  double sub_side = grid.side();
  constexpr int kMaxLevel = 40;  // sub-squares of side d * 2^-40: below any useful resolution
  for (int level = 0; level <= kMaxLevel && !active.empty(); ++level) {
    throw_darts(grid, active, sub_side, domain, options.darts_per_cell, rng, first_dart,
                options.threads, result);
    active = refine(grid, active, sub_side, domain, options.threads);
    sub_side *= 0.5;
    result.refinement_passes = level + 1;
  }

  // Sampled points in grid (row-major) order: neighbouring seeds get nearby numbers.
  for (int c = 0; c < grid.cell_count(); ++c)
    if (grid.occupied(c) && (fixed_cell.empty() || !fixed_cell[c]))
      samples.push_back(grid.sample(c));
  return result;
}

std::vector<Point> sample_boundary_points(const Rectangle& domain, double d, std::uint64_t seed) {
  check_sampler_options(domain, d);
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
