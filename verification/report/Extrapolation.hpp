#pragma once
// The limit of a quantity that converges under refinement without a known exact value (a peak
// load): least squares of q(h) = limit + c h^rate over the levels. For a fixed rate the problem
// is linear in (limit, c); the rate is the one in [kMinRate, kMaxRate] whose linear fit leaves
// the smallest residual (a golden-section search after a coarse scan). With three levels the fit
// is exact and this is Richardson extrapolation with the observed order; with more it averages.
#include <vector>

namespace vorodg {

struct Extrapolation {
  double limit = 0.0;        // q at h -> 0
  double coefficient = 0.0;  // c
  double rate = 0.0;         // the observed order of convergence
  double residual = 0.0;     // root-mean-square misfit over the levels
};

inline constexpr double kMinRate = 0.05;
inline constexpr double kMaxRate = 6.0;

/// Throws InputError for fewer than three levels, sizes that differ, or h <= 0 / non-finite.
Extrapolation extrapolate(const std::vector<double>& h, const std::vector<double>& q);

}  // namespace vorodg
