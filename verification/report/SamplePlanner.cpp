#include "verification/report/SamplePlanner.hpp"

#include <cmath>
#include <string>

#include "core/util/Errors.hpp"
#include "verification/report/CoupledDifferences.hpp"
#include "verification/report/Distributions.hpp"
#include "verification/report/EmpiricalCdf.hpp"
#include "verification/report/KolmogorovSmirnov.hpp"

namespace vorodg {
namespace {

void check_resolution(const char* what, double delta, double upper) {
  if (!(delta > 0.0 && delta < upper))
    throw InputError(std::string(what) + ": resolution " + std::to_string(delta) +
                     ": expected in (0, " + std::to_string(upper) + ")");
}

/// lambda with Q_KS(lambda) = alpha, by bisection (Q_KS falls from 1 to 0 on [0, 10]).
double kolmogorov_critical(double alpha) {
  double low = 0.0, high = 10.0;
  for (int k = 0; k < 200 && high - low > 1e-14; ++k) {
    const double mid = 0.5 * (low + high);
    (kolmogorov_survival(mid) > alpha ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

/// The smallest n >= first for which `resolved(n)` holds (it holds for every larger n).
template <class Resolved>
std::size_t smallest(std::size_t first, Resolved resolved) {
  std::size_t high = first;
  while (!resolved(high)) high *= 2;
  std::size_t low = first;  // resolved(high) holds; find the first n in [low, high]
  while (low < high) {
    const std::size_t mid = low + (high - low) / 2;
    resolved(mid) ? high = mid : low = mid + 1;
  }
  return low;
}

}  // namespace

double ks_critical_distance(double effective_size, double confidence) {
  const double root = std::sqrt(effective_size);
  return kolmogorov_critical(1.0 - confidence) / (root + 0.12 + 0.11 / root);
}

std::size_t realizations_for_ks(double delta, double confidence) {
  check_resolution("Kolmogorov-Smirnov sample size", delta, 1.0);
  return smallest(1, [&](std::size_t n) {  // n_e = n n / (n + n)
    return ks_critical_distance(0.5 * static_cast<double>(n), confidence) <= delta;
  });
}

std::size_t realizations_for_cdf_band(double delta, double confidence) {
  check_resolution("CDF band sample size", delta, 1.0);
  return smallest(1, [&](std::size_t n) { return dkw_half_width(n, confidence) <= delta; });
}

std::size_t realizations_for_mean(double std_dev, double delta, double confidence) {
  check_resolution("mean sample size", delta, HUGE_VAL);
  if (!(std_dev >= 0.0) || !std::isfinite(std_dev))
    throw InputError("mean sample size: standard deviation " + std::to_string(std_dev) +
                     ": expected a finite value >= 0");
  return smallest(2, [&](std::size_t n) {
    return student_t_critical(confidence, n) * std_dev / std::sqrt(static_cast<double>(n)) <= delta;
  });
}

std::size_t realizations_for_probability(double p, double delta, double confidence) {
  check_resolution("probability sample size", delta, 1.0);
  if (!(p >= 0.0 && p <= 1.0))
    throw InputError("probability sample size: p " + std::to_string(p) + ": expected in [0, 1]");
  const double z = normal_quantile(0.5 * (1.0 + confidence));
  return static_cast<std::size_t>(
      std::max(1.0, std::ceil(z * z * p * (1.0 - p) / (delta * delta))));
}

std::size_t realizations_to_clear(double share, double bound, double confidence) {
  check_resolution("share sample size", bound, 1.0);
  if (!(share >= 0.0 && share <= 1.0) || share == bound)
    throw InputError("share sample size: share " + std::to_string(share) +
                     ": expected in [0, 1] and not the bound " + std::to_string(bound));
  return smallest(1, [&](std::size_t n) {
    const auto hits = static_cast<std::size_t>(std::lround(share * static_cast<double>(n)));
    const Interval w = wilson_interval(hits, n, confidence);
    return share < bound ? w.high <= bound : w.low > bound;
  });
}

}  // namespace vorodg
