#include "verification/report/SampleStatistics.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace vorodg {

SampleStatistics sample_statistics(const std::vector<double>& values) {
  if (values.empty()) throw std::invalid_argument("sample_statistics: empty sample");
  const double n = static_cast<double>(values.size());
  SampleStatistics s;
  for (double x : values) s.mean += x / n;
  if (values.size() > 1) {
    double sum_of_squares = 0.0;
    for (double x : values) sum_of_squares += (x - s.mean) * (x - s.mean);
    s.std_dev = std::sqrt(sum_of_squares / (n - 1));
  }
  s.min = *std::min_element(values.begin(), values.end());
  s.max = *std::max_element(values.begin(), values.end());
  std::vector<double> sorted = values;
  std::sort(sorted.begin(), sorted.end());
  const std::size_t half = sorted.size() / 2;
  s.median = sorted.size() % 2 ? sorted[half] : 0.5 * (sorted[half - 1] + sorted[half]);
  s.values = values;
  return s;
}

}  // namespace vorodg
