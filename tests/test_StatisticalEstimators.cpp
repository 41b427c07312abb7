// The statistical estimators of the report (verification/report): the empirical CDF and its DKW
// band, the Wasserstein-1 distance, the bootstrap intervals, the coupled differences between two
// levels, and the sample-size planner. Closed forms and hand cases; reference values from scipy
// 1.10.1 (the call is written beside each) or, where scipy is off, mpmath at 40 digits; coverage
// of the intervals measured on fixed seeds.
//
// scipy 1.10.1's t.ppf(0.975, 11) is 2.200985160082949, 4e-12 relative below the quantile
// (mpmath: 2.2009851600916398..., which Boost.Math gives): its Student-t intervals are off by as
// much, so they are compared with a tolerance of 1e-9 in python/tests.
// The same estimators are checked against scipy on random samples in python/tests.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "core/util/Errors.hpp"
#include "verification/report/Bootstrap.hpp"
#include "verification/report/CoupledDifferences.hpp"
#include "verification/report/Distributions.hpp"
#include "verification/report/EmpiricalCdf.hpp"
#include "verification/report/KolmogorovSmirnov.hpp"
#include "verification/report/SamplePlanner.hpp"
#include "verification/report/Wasserstein.hpp"

namespace vorodg {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<double> normal_sample(std::mt19937_64& rng, std::size_t n, double mean = 0.0) {
  std::normal_distribution<double> z(mean, 1.0);
  std::vector<double> v(n);
  for (double& x : v) x = z(rng);
  return v;
}

double mean_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) s += (a[i] - b[i]) / static_cast<double>(a.size());
  return s;
}

TEST(Distributions, QuantilesMatchScipy) {
  EXPECT_NEAR(normal_quantile(0.975), 1.959963984540054, 1e-14);           // norm.ppf(0.975)
  EXPECT_NEAR(normal_quantile(0.1), -1.2815515655446004, 1e-14);           // norm.ppf(0.1)
  EXPECT_NEAR(student_t_quantile(0.975, 11), 2.2009851600916398, 1e-14);   // mpmath
  EXPECT_NEAR(student_t_quantile(0.05, 3.5), -2.2224334936496015, 1e-13);  // mpmath
  EXPECT_NEAR(student_t_critical(0.95, 12), 2.2009851600916398, 1e-14);
  EXPECT_THROW(normal_quantile(1.0), InputError);
  EXPECT_THROW(student_t_quantile(0.5, 0.0), InputError);
  EXPECT_THROW(student_t_critical(0.95, 1), InputError);
}

TEST(Distributions, StudentTMatchesThePrintedTable) {
  // Two-sided 95% values of Student's t (any statistics table; scipy.stats.t.ppf(0.975, dof)).
  const std::pair<int, double> table[] = {
      {1, 12.706204736432095},  {2, 4.302652729911275},    {5, 2.5705818366147395},
      {10, 2.2281388519649385}, {30, 2.0422724563012373},  {31, 2.0395134463964077},
      {60, 2.0002978210582616}, {120, 1.9799304050527766}, {1000, 1.9623390808264074}};
  for (const auto& [dof, t] : table)
    EXPECT_NEAR(student_t_quantile(0.975, static_cast<double>(dof)), t, 1e-9 * t) << dof;
  EXPECT_THROW(student_t_quantile(0.975, 0), InputError);
  EXPECT_THROW(student_t_quantile(1.0, 3), InputError);
}

TEST(EmpiricalCdf, StepsAndQuantilesByHand) {
  const EmpiricalCdf f({4, 1, 3, 2, 10});
  EXPECT_EQ(f(0.5), 0.0);
  EXPECT_EQ(f(1.0), 0.2);  // at or below
  EXPECT_EQ(f(3.5), 0.6);
  EXPECT_EQ(f(10.0), 1.0);
  // numpy.quantile([4, 1, 3, 2, 10], [0.1, 0.25, 0.5, 0.9]) (type 7)
  EXPECT_NEAR(f.quantile(0.1), 1.4, 1e-14);
  EXPECT_NEAR(f.quantile(0.25), 2.0, 1e-14);
  EXPECT_NEAR(f.quantile(0.5), 3.0, 1e-14);
  EXPECT_NEAR(f.quantile(0.9), 7.6, 1e-14);
  EXPECT_EQ(f.quantile(1.0), 10.0);
  EXPECT_THROW(EmpiricalCdf({}), InputError);
  EXPECT_THROW(EmpiricalCdf({1.0, kNaN}), InputError);
}

TEST(EmpiricalCdf, DkwHalfWidthIsMassartsBound) {
  // 2 exp(-2 n eps^2) = 0.05 at n = 100: eps = sqrt(ln 40 / 200).
  EXPECT_NEAR(dkw_half_width(100, 0.95), std::sqrt(std::log(40.0) / 200.0), 1e-15);
  const EmpiricalCdf f({0.1, 0.2, 0.3, 0.4});
  const auto [low, high] = f.dkw_band(0.25);  // F_n = 0.5, eps = sqrt(ln 40 / 8) = 0.679
  EXPECT_EQ(low, 0.0);                        // both ends clipped
  EXPECT_EQ(high, 1.0);
  std::vector<double> hundred(100);
  for (std::size_t i = 0; i < hundred.size(); ++i) hundred[i] = static_cast<double>(i);
  const auto [below, above] = EmpiricalCdf(hundred).dkw_band(49.5);  // F_n = 0.5
  EXPECT_NEAR(below, 0.5 - dkw_half_width(100), 1e-15);
  EXPECT_NEAR(above, 0.5 + dkw_half_width(100), 1e-15);
}

TEST(EmpiricalCdf, DkwBandHoldsTheTrueCdfAtLeastAsOftenAsPromised) {
  // 2000 samples of 40 uniforms: sup |F_n - x| <= eps in at least 94 % of them (95 % promised,
  // less about two standard errors of a share, 0.01); the bound is conservative: numpy's
  // generator gives 96.3 % for the same experiment.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::size_t n = 40, trials = 2000;
  const double eps = dkw_half_width(n, 0.95);
  std::size_t held = 0;
  for (std::size_t t = 0; t < trials; ++t) {
    std::vector<double> x(n);
    for (double& v : x) v = u(rng);
    const EmpiricalCdf f(x);
    double sup = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double xi = f.sorted()[i];
      sup = std::max({sup, (i + 1.0) / n - xi, xi - static_cast<double>(i) / n});
    }
    held += sup <= eps ? 1 : 0;
  }
  EXPECT_GE(static_cast<double>(held) / trials, 0.94);
}

TEST(Wasserstein, MatchesHandCasesAndScipy) {
  EXPECT_NEAR(wasserstein1({1, 2, 3, 4}, {2.5, 5, 6}), 2.0, 1e-14);  // by hand; scipy: 2.0
  // scipy.stats.wasserstein_distance([0.3, -1, 2.5, 2.5, 7], [1, 1, 4]) = 1.74
  EXPECT_NEAR(wasserstein1({0.3, -1, 2.5, 2.5, 7}, {1, 1, 4}), 1.74, 1e-14);
  EXPECT_EQ(wasserstein1({3, 1, 2}, {2, 3, 1}), 0.0);
  EXPECT_THROW(wasserstein1({1.0}, {}), InputError);
}

TEST(Wasserstein, IsTheShiftForATranslateAndTheMeanGapOfOrderStatistics) {
  std::mt19937_64 rng(11);
  const std::vector<double> a = normal_sample(rng, 50);
  std::vector<double> shifted = a, b = normal_sample(rng, 50);
  for (double& x : shifted) x += 0.37;
  EXPECT_NEAR(wasserstein1(a, shifted), 0.37, 1e-12);
  // Equal sizes: W1 = mean |a_(i) - b_(i)| over the sorted samples.
  std::vector<double> as = a, bs = b;
  std::sort(as.begin(), as.end());
  std::sort(bs.begin(), bs.end());
  double expected = 0.0;
  for (std::size_t i = 0; i < as.size(); ++i) expected += std::abs(as[i] - bs[i]) / 50.0;
  EXPECT_NEAR(wasserstein1(a, b), expected, 1e-12);
  EXPECT_NEAR(wasserstein1(a, b), wasserstein1(b, a), 1e-15);
}

TEST(Bootstrap, IsReproducibleAndNearTheStudentIntervalForAMean) {
  std::mt19937_64 rng(3);
  const std::vector<double> a = normal_sample(rng, 60), b = normal_sample(rng, 60, 0.5);
  const Interval first = bootstrap_paired(a, b, mean_difference);
  const Interval again = bootstrap_paired(a, b, mean_difference);
  EXPECT_EQ(first.low, again.low);
  EXPECT_EQ(first.high, again.high);
  std::vector<double> d(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) d[i] = a[i] - b[i];
  const Interval t = mean_interval(d);
  EXPECT_NEAR(first.estimate, t.estimate, 1e-14);
  // The percentile interval of a mean is the t interval to O(1/n) and its resampling error.
  const double width = t.high - t.low;
  EXPECT_NEAR(first.low, t.low, 0.15 * width);
  EXPECT_NEAR(first.high, t.high, 0.15 * width);
}

TEST(Bootstrap, KeepingTheCouplingNarrowsTheIntervalOfADifference) {
  // b = a + small noise: the paired interval of the mean difference is far narrower than the one
  // that resamples the two on their own, which sees two independent spreads of 1.
  std::mt19937_64 rng(5);
  const std::vector<double> a = normal_sample(rng, 40);
  std::vector<double> b = a;
  std::normal_distribution<double> noise(0.0, 0.05);
  for (double& x : b) x += noise(rng);
  const auto mean_gap = [](const std::vector<double>& x, const std::vector<double>& y) {
    double s = 0.0;
    for (double v : x) s += v / static_cast<double>(x.size());
    for (double v : y) s -= v / static_cast<double>(y.size());
    return s;
  };
  const Interval paired = bootstrap_paired(a, b, mean_gap);
  const Interval independent = bootstrap_independent(a, b, mean_gap);
  EXPECT_LT(paired.high - paired.low, 0.1 * (independent.high - independent.low));
  EXPECT_THROW(bootstrap_paired(a, {1.0, 2.0}, mean_gap), InputError);
  EXPECT_THROW(bootstrap_independent(a, b, mean_gap, {.resamples = 5}), InputError);
}

TEST(CoupledDifferences, ByHand) {
  // D = 1, -2, 0.5, 0: |D| = 1, 2, 0.5, 0; D^2 = 1, 4, 0.25, 0; beyond 0.6: two of four.
  const CoupledDifferences r = coupled_differences({3, 1, 2.5, 4}, {2, 3, 2, 4}, 0.6);
  EXPECT_EQ(r.pairs, 4u);
  EXPECT_NEAR(r.mean_difference.estimate, -0.125, 1e-15);
  EXPECT_NEAR(r.mean_absolute.estimate, 0.875, 1e-15);
  EXPECT_NEAR(r.mean_square.estimate, 1.3125, 1e-15);
  EXPECT_NEAR(r.exceedance.estimate, 0.5, 1e-15);
  EXPECT_GE(r.mean_absolute.low, 0.0);  // clipped: a mean of non-negative values
  EXPECT_GE(r.mean_square.low, 0.0);
  EXPECT_THROW(coupled_differences({1, 2}, {1, 2, 3}, 0.1), InputError);
  EXPECT_THROW(coupled_differences({1}, {1}, 0.1), InputError);
  EXPECT_THROW(coupled_differences({1, 2}, {1, 2}, -1.0), InputError);
  EXPECT_THROW(coupled_differences({1, kNaN}, {1, 2}, 0.1), InputError);
}

TEST(CoupledDifferences, IntervalsMatchScipy) {
  // mean(x) -+ t_5 sem(x), x = [3.1, 2.7, 4.0, 3.3, 2.9, 3.8], in mpmath (scipy's t.interval:
  // 2.7648907191873895 and 3.835109280812611: its t.ppf(0.975, 5) is 4e-10 relative off)
  const Interval m = mean_interval({3.1, 2.7, 4.0, 3.3, 2.9, 3.8});
  EXPECT_NEAR(m.low, 2.7648907193910643, 1e-13);
  EXPECT_NEAR(m.high, 3.8351092806089357, 1e-13);
  // scipy.stats.binomtest(k, 12).proportion_ci(0.95, 'wilson')
  const Interval w = wilson_interval(3, 12);
  EXPECT_NEAR(w.low, 0.08894166839405471, 1e-12);
  EXPECT_NEAR(w.high, 0.5323053349335657, 1e-12);
  const Interval none = wilson_interval(0, 12);
  EXPECT_NEAR(none.low, 0.0, 1e-15);
  EXPECT_NEAR(none.high, 0.24249400665524085, 1e-12);
  EXPECT_THROW(wilson_interval(3, 2), InputError);
}

TEST(CoupledDifferences, TheMeanCanConvergeWhileTheRealizationsDoNot) {
  // The report's warning (section 5): q_h = X and q_{h/2} = -X for a symmetric X have the same
  // law and the same mean, yet |q_h - q_{h/2}| = 2 |X| does not shrink. The interval of the mean
  // difference holds 0; those of E|D| and Pr(|D| > 0.5) do not.
  std::mt19937_64 rng(13);
  const std::vector<double> x = normal_sample(rng, 400);
  std::vector<double> minus = x;
  for (double& v : minus) v = -v;
  const CoupledDifferences r = coupled_differences(x, minus, 0.5);
  EXPECT_TRUE(r.mean_difference.contains(0.0));
  EXPECT_GT(r.mean_absolute.low, 1.0);  // E 2|X| = 2 sqrt(2 / pi) = 1.60
  EXPECT_TRUE(r.mean_absolute.contains(2.0 * std::sqrt(2.0 / M_PI)));
  EXPECT_TRUE(r.mean_square.contains(4.0));          // E 4 X^2
  EXPECT_GT(r.exceedance.low, 0.7);                  // Pr(2|X| > 0.5) = 0.803
  EXPECT_GT(ks_two_sample(x, minus).p_value, 0.05);  // while their laws agree
}

TEST(CoupledDifferences, TheStudentIntervalCoversTheMeanAtItsConfidence) {
  // 2000 samples of 12 normals: the 95 % interval holds the mean in 95 % +- 3 standard errors.
  std::mt19937_64 rng(17);
  std::size_t held = 0;
  const std::size_t trials = 2000;
  for (std::size_t t = 0; t < trials; ++t)
    held += mean_interval(normal_sample(rng, 12, 1.5)).contains(1.5);
  EXPECT_NEAR(static_cast<double>(held) / trials, 0.95, 3.0 * std::sqrt(0.95 * 0.05 / trials));
}

TEST(SamplePlanner, SizesAreTheSmallestThatResolve) {
  // KS: the critical distance lambda / (sqrt(n/2) + 0.12 + 0.11 / sqrt(n/2)), with
  // lambda = scipy.stats.kstwobign.isf(0.05) = 1.3580986393225507, at most delta at n, not at n-1.
  const double lambda = 1.3580986393225507;
  const auto critical = [&](double n) {
    const double r = std::sqrt(n / 2.0);
    return lambda / (r + 0.12 + 0.11 / r);
  };
  for (double delta : {0.5, 0.2, 0.1, 0.05}) {
    const auto n = static_cast<double>(realizations_for_ks(delta));
    EXPECT_LE(critical(n), delta * (1 + 1e-12));
    EXPECT_GT(critical(n - 1), delta);
  }
  EXPECT_EQ(realizations_for_cdf_band(0.05), 738u);  // ln 40 / (2 0.05^2) = 737.78
  // The mean: t_{n-1} / sqrt(n) is 0.5142 at n = 17 and 0.4973 at n = 18 (scipy t.ppf).
  const std::size_t m = realizations_for_mean(1.0, 0.5);
  EXPECT_EQ(m, 18u);
  EXPECT_LE(student_t_critical(0.95, m) / std::sqrt(double(m)), 0.5);
  EXPECT_GT(student_t_critical(0.95, m - 1) / std::sqrt(double(m - 1)), 0.5);
  EXPECT_EQ(realizations_for_probability(0.5, 0.1), 97u);  // 1.96^2 / 4 / 0.01 = 96.04
  EXPECT_EQ(realizations_for_probability(0.0, 0.1), 1u);
  // A share of 0 against a bound of 0.1: the Wilson upper end z^2 / (n + z^2) <= 0.1 first at
  // n = 35 (3.8415 * 9 = 34.57); a share of 0.3 stays above 0.1 from the n where its interval
  // clears it, checked against the interval itself.
  EXPECT_EQ(realizations_to_clear(0.0, 0.1), 35u);
  const std::size_t clear = realizations_to_clear(0.3, 0.1);
  EXPECT_GT(wilson_interval(std::lround(0.3 * clear), clear).low, 0.1);
  EXPECT_LE(wilson_interval(std::lround(0.3 * (clear - 1)), clear - 1).low, 0.1);
  EXPECT_THROW(realizations_to_clear(0.1, 0.1), InputError);
  EXPECT_THROW(realizations_for_ks(0.0), InputError);
  EXPECT_THROW(realizations_for_mean(-1.0, 0.1), InputError);
}

}  // namespace
}  // namespace vorodg
