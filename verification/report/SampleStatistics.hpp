#pragma once
// Mean, median, standard deviation and range of a sample of realizations. The spread is defined
// only for two or more values: with one realization there is no spread to report.
#include <optional>
#include <vector>

namespace vorodg {

struct SampleStatistics {
  double mean = 0.0;
  std::optional<double> std_dev;  // sample (n - 1) standard deviation; none for n < 2
  double min = 0.0, max = 0.0;
  double median = 0.0;         // the middle value, or the mean of the two middle ones
  std::vector<double> values;  // in the order given (for CDFs)
};

/// Statistics of a non-empty sample; throws std::invalid_argument for an empty one.
SampleStatistics sample_statistics(const std::vector<double>& values);

}  // namespace vorodg
