#pragma once
// What a coupled pair of levels says about convergence. Realization i at h and at h/2 share their
// random material field and seed (only the mesh differs), so the difference
// D_i = q_h(i) - q_{h/2}(i) is defined per realization, and with it the report's notions that need
// the two on one probability space (SAND2008-6089, section 5):
// - in r-th mean: E|q_h - q_{h/2}|^r -> 0, estimated for r = 1 and 2 (Student t interval);
// - in probability: Pr(|q_h - q_{h/2}| > eps) -> 0 (Wilson score interval);
// and beside them the convergence *of* the mean, E q_h - E q_{h/2} (paired t interval), which can
// vanish while the realizations still differ: it is not convergence in mean.
#include <vector>

#include "verification/report/Interval.hpp"

namespace vorodg {

struct CoupledDifferences {
  std::size_t pairs = 0;
  Interval mean_difference;  // E[q_h - q_{h/2}]
  Interval mean_absolute;    // E|q_h - q_{h/2}|      (r = 1)
  Interval mean_square;      // E|q_h - q_{h/2}|^2    (r = 2)
  Interval exceedance;       // Pr(|q_h - q_{h/2}| > epsilon)
  double epsilon = 0.0;
  double difference_std_dev = 0.0, absolute_std_dev = 0.0;  // of D and |D|: for the planner
};

/// coarse[i] and fine[i] from realization i; at least two pairs, every value finite, epsilon >= 0.
/// The intervals of E|D| and E|D|^2 are clipped at 0 below (a mean of non-negative values).
CoupledDifferences coupled_differences(const std::vector<double>& coarse,
                                       const std::vector<double>& fine, double epsilon,
                                       double confidence = 0.95);

/// The Student t interval of a sample's mean (n >= 2).
Interval mean_interval(const std::vector<double>& values, double confidence = 0.95);

/// The Wilson score interval of a probability from `hits` successes in `trials` (trials >= 1).
Interval wilson_interval(std::size_t hits, std::size_t trials, double confidence = 0.95);

}  // namespace vorodg
