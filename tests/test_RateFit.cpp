// The one rate fit behind every published rate (verification/report/RateFit): a hand-computed
// regression, exact power laws, and Student's t quantiles against a printed table.
#include "verification/report/RateFit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace vorodg {
namespace {

TEST(RateFit, ReproducesAHandComputedRegression) {
  // log e against log h by hand (and by scipy.stats.linregress): slope 1.98865..., intercept
  // -1.64127..., standard error of the slope times t(0.975, 2) = 0.12352...
  const RateFit fit = fit_rate({0.4, 0.2, 0.1, 0.05}, {3.1e-2, 8.2e-3, 1.9e-3, 5.1e-4});
  EXPECT_NEAR(fit.rate, 1.9886505965744814, 1e-13);
  EXPECT_NEAR(fit.intercept, -1.6412741642872515, 1e-13);
  ASSERT_TRUE(fit.ci95.has_value());
  EXPECT_NEAR(*fit.ci95, 0.1235253082757234, 1e-10);
  EXPECT_EQ(fit.points, 4);
}

TEST(RateFit, AnExactPowerLawHasItsExponentAndNoSpread) {
  const std::vector<double> h = {1.0, 0.3, 0.07, 0.01};
  std::vector<double> e;
  for (double x : h) e.push_back(3.0 * std::pow(x, 2.5));
  const RateFit fit = fit_rate(h, e);
  EXPECT_NEAR(fit.rate, 2.5, 1e-13);
  EXPECT_NEAR(fit.intercept, std::log(3.0), 1e-13);
  EXPECT_NEAR(*fit.ci95, 0.0, 1e-12);
}

TEST(RateFit, TwoPointsGiveARateButNoInterval) {
  const RateFit fit = fit_rate({0.1, 0.05}, {1e-2, 2.5e-3});
  EXPECT_NEAR(fit.rate, 2.0, 1e-14);
  EXPECT_FALSE(fit.ci95.has_value());
  EXPECT_NEAR(pair_rate(0.1, 1e-2, 0.05, 2.5e-3), 2.0, 1e-14);
}

TEST(RateFit, RefusesTooFewOrMismatchedPoints) {
  EXPECT_THROW(fit_rate({0.1}, {0.01}), std::invalid_argument);
  EXPECT_THROW(fit_rate({0.1, 0.05}, {0.01}), std::invalid_argument);
}

}  // namespace
}  // namespace vorodg
