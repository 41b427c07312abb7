#include "verification/report/CoupledDifferences.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/util/Errors.hpp"
#include "verification/report/CheckedSample.hpp"
#include "verification/report/Distributions.hpp"
#include "verification/report/SampleStatistics.hpp"

namespace vorodg {

Interval mean_interval(const std::vector<double>& values, double confidence) {
  check_sample("mean interval", values);
  const SampleStatistics s = sample_statistics(values);
  const double t = student_t_critical(confidence, values.size());
  const double half = t * *s.std_dev / std::sqrt(static_cast<double>(values.size()));
  return {s.mean, s.mean - half, s.mean + half};
}

Interval wilson_interval(std::size_t hits, std::size_t trials, double confidence) {
  if (trials == 0 || hits > trials)
    throw InputError("Wilson interval: " + std::to_string(hits) + " hits in " +
                     std::to_string(trials) + " trials: expected 0 <= hits <= trials, trials >= 1");
  const double n = static_cast<double>(trials), p = static_cast<double>(hits) / n;
  const double z = normal_quantile(0.5 * (1.0 + confidence)), z2 = z * z;
  const double centre = (p + z2 / (2.0 * n)) / (1.0 + z2 / n);
  const double half = z / (1.0 + z2 / n) * std::sqrt(p * (1.0 - p) / n + z2 / (4.0 * n * n));
  return {p, std::max(0.0, centre - half), std::min(1.0, centre + half)};
}

CoupledDifferences coupled_differences(const std::vector<double>& coarse,
                                       const std::vector<double>& fine, double epsilon,
                                       double confidence) {
  check_sample("coupled differences", coarse);
  check_sample("coupled differences", fine);
  if (coarse.size() != fine.size() || coarse.size() < 2)
    throw InputError("coupled differences: " + std::to_string(coarse.size()) + " and " +
                     std::to_string(fine.size()) +
                     " values: expected one pair per realization, at least 2");
  if (!(epsilon >= 0.0) || !std::isfinite(epsilon))
    throw InputError("coupled differences: epsilon " + std::to_string(epsilon) +
                     ": expected a finite value >= 0");
  std::vector<double> difference(coarse.size()), absolute(coarse.size()), square(coarse.size());
  std::size_t exceeding = 0;
  for (std::size_t i = 0; i < coarse.size(); ++i) {
    difference[i] = coarse[i] - fine[i];
    absolute[i] = std::abs(difference[i]);
    square[i] = difference[i] * difference[i];
    exceeding += absolute[i] > epsilon ? 1 : 0;
  }
  const auto non_negative = [](Interval i) {
    i.low = std::max(0.0, i.low);
    return i;
  };
  CoupledDifferences r;
  r.pairs = coarse.size();
  r.epsilon = epsilon;
  r.mean_difference = mean_interval(difference, confidence);
  r.mean_absolute = non_negative(mean_interval(absolute, confidence));
  r.mean_square = non_negative(mean_interval(square, confidence));
  r.exceedance = wilson_interval(exceeding, coarse.size(), confidence);
  r.difference_std_dev = *sample_statistics(difference).std_dev;
  r.absolute_std_dev = *sample_statistics(absolute).std_dev;
  return r;
}

}  // namespace vorodg
