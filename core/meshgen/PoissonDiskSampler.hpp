#pragma once
// Randomly close-packed seeds (report section 2): random sequential addition of points with a
// minimum distance d until the packing is saturated (maximal: no point of the domain is farther
// than d from every seed). Algorithm: maximal Poisson-disk sampling on a background grid with
// uniform refinement of the still-uncovered grid cells (Ebeida et al., "Efficient maximal
// Poisson-disk sampling", 2011): unbiased, O(N) expected, and it ends at saturation rather than
// on a rejection count.
#include <cstdint>
#include <vector>

#include "core/geometry/Rectangle.hpp"

namespace vorodg {

struct PoissonDiskOptions {
  double min_distance = 0.1;  // d
  std::uint64_t seed = 1;
  /// Darts thrown per active grid cell in each refinement pass.
  double darts_per_cell = 1.0;
  /// Points fixed before sampling starts (e.g. seeds on the boundary); they must already be at
  /// least d apart and inside the domain.
  std::vector<Point> fixed_points;
  /// Threads for the tests against the grid, the resolution of arrivals and the refinement; the
  /// random numbers are drawn in one sequence, so the samples do not depend on it.
  int threads = 1;
};

struct PoissonDiskResult {
  std::vector<Point> points;  // fixed points first, then sampled ones in grid order
  int refinement_passes = 0;
  std::uint64_t darts_thrown = 0;
};

/// Samples the rectangle to saturation. Throws InputError if d is not positive and finite or
/// exceeds the domain's larger side.
PoissonDiskResult sample_poisson_disk(const Rectangle& domain, const PoissonDiskOptions& options);

/// Maximal 1D random sequential addition on the domain sides with spacing d, corners included:
/// boundary seeds for meshes whose vertices must cover the sides (the `tri` family).
std::vector<Point> sample_boundary_points(const Rectangle& domain, double d, std::uint64_t seed);

/// Fraction of `area` covered by disks of diameter d around the given points
/// (N * pi d^2 / 4 / area). Saturated random sequential addition reaches about 0.547.
double covered_fraction(std::size_t n_points, double d, double area);

}  // namespace vorodg
