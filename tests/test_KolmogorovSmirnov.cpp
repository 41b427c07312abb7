// The two-sample Kolmogorov-Smirnov test (verification/report/KolmogorovSmirnov): distances
// computed by hand, the extreme cases, ties, symmetry, and the asymptotic p-value with Stephens'
// correction against values of the header's formula.
//
// The reference p-values are scipy.stats.kstwobign.sf((sqrt(n_e) + 0.12 + 0.11 / sqrt(n_e)) D)
// (scipy 1.10.1), i.e. the header's formula. scipy.stats.ks_2samp(..., method='asymp') does NOT
// give them: for a two-sided test it returns kstwo.sf(D, round(n_e)) (0.2222 for the hand case
// below), and the uncorrected kstwobign.sf(sqrt(n_e) D) is 0.4313 there.
#include "verification/report/KolmogorovSmirnov.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

/// Q_KS(lambda) with lambda = (sqrt(n_e) + 0.12 + 0.11 / sqrt(n_e)) D, summed here on its own so
/// the test does not share the implementation's series.
double stephens_p(double d, double n, double m) {
  const double s = std::sqrt(n * m / (n + m)), x = (s + 0.12 + 0.11 / s) * d;
  double sum = 0.0;
  for (int k = 1; k <= 100; ++k) sum += (k % 2 ? 2.0 : -2.0) * std::exp(-2.0 * k * k * x * x);
  return sum;
}

TEST(KolmogorovSmirnov, IdenticalSamplesHaveNoDistance) {
  const std::vector<double> a = {0.3, -1.0, 2.5, 2.5, 7.0};
  const KsResult r = ks_two_sample(a, a);
  EXPECT_EQ(r.distance, 0.0);
  EXPECT_EQ(r.p_value, 1.0);
}

TEST(KolmogorovSmirnov, DisjointSamplesAreAtDistanceOne) {
  const KsResult r = ks_two_sample({5, 1, 3, 2, 4}, {14, 10, 12, 11, 13});
  EXPECT_EQ(r.distance, 1.0);
  EXPECT_NEAR(r.p_value, 0.003781354059370101, 1e-12);  // scipy kstwobign, n_e = 2.5
}

TEST(KolmogorovSmirnov, MatchesAHandComputedCase) {
  // Pooled 1a 2a 2.5b 3a 4a 5b 6b: F_a - F_b = 1/4, 1/2, 1/6, 5/12, 2/3, 1/3, 0; the largest is
  // 2/3, just after 4. n_e = 12/7.
  const KsResult r = ks_two_sample({1, 2, 3, 4}, {2.5, 5, 6});
  EXPECT_NEAR(r.distance, 2.0 / 3.0, 1e-14);
  EXPECT_NEAR(r.p_value, 0.2606013691025789, 1e-12);  // scipy kstwobign, Stephens' lambda
  EXPECT_NEAR(r.p_value, stephens_p(2.0 / 3.0, 4, 3), 1e-12);
}

TEST(KolmogorovSmirnov, TiesStepBothDistributionsTogether) {
  // At x = 2 both CDFs jump (a to 3/4, b to 2/3): a gap of 3/4 - 0 must not be seen in between.
  // Gaps 1/4, 1/12, 1/3, 0: D = 1/3.
  const KsResult r = ks_two_sample({1, 2, 2, 3}, {2, 2, 4});
  EXPECT_NEAR(r.distance, 1.0 / 3.0, 1e-14);
  EXPECT_NEAR(r.p_value, 0.9610338462893631, 1e-12);  // scipy kstwobign, Stephens' lambda
}

TEST(KolmogorovSmirnov, LargerSamplesFollowTheHeaderFormula) {
  std::vector<double> a, b;  // 0.1 ... 3.0 against 0.55 ... 2.925: D = 1/6 (by scipy too)
  for (int i = 1; i <= 30; ++i) a.push_back(i / 10.0);
  for (int i = 0; i < 20; ++i) b.push_back(0.55 + i / 8.0);
  const KsResult r = ks_two_sample(a, b);
  EXPECT_NEAR(r.distance, 1.0 / 6.0, 1e-14);
  EXPECT_NEAR(r.p_value, 0.8607643516606699, 1e-12);  // scipy kstwobign, Stephens' lambda
  EXPECT_NEAR(r.p_value, stephens_p(1.0 / 6.0, 30, 20), 1e-12);
}

TEST(KolmogorovSmirnov, IsSymmetricInItsSamples) {
  const std::vector<double> a = {0.2, 1.7, 0.9, 3.3, 2.0, 2.0}, b = {1.1, 2.0, 0.4, 5.0};
  const KsResult ab = ks_two_sample(a, b), ba = ks_two_sample(b, a);
  EXPECT_EQ(ab.distance, ba.distance);
  EXPECT_EQ(ab.p_value, ba.p_value);
}

TEST(KolmogorovSmirnov, RefusesAnEmptyOrNonFiniteSample) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(ks_two_sample({}, {1.0}), InputError);
  EXPECT_THROW(ks_two_sample({1.0}, {}), InputError);
  EXPECT_THROW(ks_two_sample({1.0, nan}, {1.0}), InputError);
  EXPECT_THROW(ks_two_sample({1.0}, {nan}), InputError);
  EXPECT_THROW(ks_two_sample({1.0}, {2.0, inf}), InputError);
}

}  // namespace
}  // namespace vorodg
