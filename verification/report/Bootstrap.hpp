#pragma once
// Percentile bootstrap intervals for the report's statistics between two levels. Independent
// levels (a fresh mesh per level) resample each sample on its own; coupled levels (the same random
// field and seed at both) resample the pairs, keeping the coupling. The generator is seeded, so an
// interval is the same on every rerun.
//
// A percentile interval of a distance (KS, W1) does not hold 0 even when the two laws are equal:
// the sample distance is biased upwards by about its own sampling spread. The report therefore
// decides "the same law" with the KS test's p-value, and reads W1's interval as a size.
#include <cstdint>
#include <functional>
#include <vector>

#include "verification/report/Interval.hpp"

namespace vorodg {

struct BootstrapOptions {
  int resamples = 2000;
  double confidence = 0.95;
  std::uint64_t seed = 20080925;  // fixed: the same interval on every rerun
};

using TwoSampleStatistic =
    std::function<double(const std::vector<double>& a, const std::vector<double>& b)>;

/// The statistic on (a, b) and its percentile interval, a and b resampled independently.
Interval bootstrap_independent(const std::vector<double>& a, const std::vector<double>& b,
                               const TwoSampleStatistic& statistic,
                               const BootstrapOptions& options = {});

/// The same for paired values (a[i] and b[i] from one realization): the pairs are resampled.
/// Throws InputError if the sizes differ.
Interval bootstrap_paired(const std::vector<double>& a, const std::vector<double>& b,
                          const TwoSampleStatistic& statistic,
                          const BootstrapOptions& options = {});

}  // namespace vorodg
