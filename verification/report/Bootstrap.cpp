#include "verification/report/Bootstrap.hpp"

#include <random>
#include <string>

#include "core/util/Errors.hpp"
#include "verification/report/CheckedSample.hpp"
#include "verification/report/EmpiricalCdf.hpp"

namespace vorodg {
namespace {

void check_options(const BootstrapOptions& o) {
  if (o.resamples < 10)
    throw InputError("bootstrap: resamples " + std::to_string(o.resamples) + ": expected >= 10");
  if (!(o.confidence > 0.0 && o.confidence < 1.0))
    throw InputError("bootstrap: confidence " + std::to_string(o.confidence) +
                     ": expected in (0, 1)");
}

/// An index in [0, n) from 53 random bits (the same on every standard library, unlike
/// std::uniform_int_distribution).
std::size_t draw_index(std::mt19937_64& rng, std::size_t n) {
  const double u = static_cast<double>(rng() >> 11) * 0x1.0p-53;
  return std::min(n - 1, static_cast<std::size_t>(u * static_cast<double>(n)));
}

/// `count` draws of the percentile interval's statistic, `resample` filling (a*, b*) each time.
template <class Resample>
Interval percentile_interval(double estimate, const TwoSampleStatistic& statistic,
                             const BootstrapOptions& o, Resample resample) {
  std::mt19937_64 rng(o.seed);
  std::vector<double> draws(static_cast<std::size_t>(o.resamples)), ra, rb;
  for (double& d : draws) {
    resample(rng, ra, rb);
    d = statistic(ra, rb);
  }
  const EmpiricalCdf cdf(std::move(draws), "bootstrap statistic");
  return {estimate, cdf.quantile(0.5 * (1.0 - o.confidence)),
          cdf.quantile(0.5 * (1.0 + o.confidence))};
}

void resample_from(std::mt19937_64& rng, const std::vector<double>& from, std::vector<double>& to) {
  to.resize(from.size());
  for (double& v : to) v = from[draw_index(rng, from.size())];
}

}  // namespace

Interval bootstrap_independent(const std::vector<double>& a, const std::vector<double>& b,
                               const TwoSampleStatistic& statistic, const BootstrapOptions& o) {
  check_options(o);
  check_sample("bootstrap", a);
  check_sample("bootstrap", b);
  return percentile_interval(statistic(a, b), statistic, o, [&](auto& rng, auto& ra, auto& rb) {
    resample_from(rng, a, ra);
    resample_from(rng, b, rb);
  });
}

Interval bootstrap_paired(const std::vector<double>& a, const std::vector<double>& b,
                          const TwoSampleStatistic& statistic, const BootstrapOptions& o) {
  check_options(o);
  check_sample("bootstrap", a);
  check_sample("bootstrap", b);
  if (a.size() != b.size())
    throw InputError("paired bootstrap: " + std::to_string(a.size()) + " and " +
                     std::to_string(b.size()) + " values: expected one pair per realization");
  return percentile_interval(statistic(a, b), statistic, o, [&](auto& rng, auto& ra, auto& rb) {
    ra.resize(a.size());
    rb.resize(b.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
      const std::size_t i = draw_index(rng, a.size());
      ra[k] = a[i];
      rb[k] = b[i];
    }
  });
}

}  // namespace vorodg
