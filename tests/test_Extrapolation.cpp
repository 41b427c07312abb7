// The extrapolation to h -> 0 of a converging quantity (verification/report/Extrapolation):
// exact data q = limit + c h^p on random-looking sizes give back limit, c and p; three levels
// are Richardson extrapolation (exact fit); bad input is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/util/Errors.hpp"
#include "verification/report/Extrapolation.hpp"

namespace vorodg {
namespace {

std::vector<double> exact(const std::vector<double>& h, double limit, double c, double p) {
  std::vector<double> q;
  for (double x : h) q.push_back(limit + c * std::pow(x, p));
  return q;
}

TEST(Extrapolation, RecoversAnExactPowerLaw) {
  const std::vector<double> h{0.041, 0.0197, 0.0102, 0.0049};  // not halving: rcp levels
  for (double p : {0.5, 1.0, 1.5, 2.0, 3.0}) {
    const Extrapolation e = extrapolate(h, exact(h, 880.0, -4000.0, p));
    EXPECT_NEAR(e.rate, p, 1e-6 * p) << "p = " << p;
    EXPECT_NEAR(e.limit, 880.0, 1e-7 * 880.0) << "p = " << p;
    EXPECT_LE(e.residual, 1e-8 * 880.0) << "p = " << p;
  }
}

TEST(Extrapolation, ThreeLevelsFitExactly) {
  const std::vector<double> h{0.04, 0.02, 0.01}, q{900.0, 885.0, 881.0};
  const Extrapolation e = extrapolate(h, q);
  // Richardson with the observed order: p = log2(15 / 4), limit = q3 - 4 / (2^p - 1).
  const double p = std::log2(15.0 / 4.0);
  EXPECT_NEAR(e.rate, p, 1e-6);
  EXPECT_NEAR(e.limit, 881.0 - 4.0 / (std::pow(2.0, p) - 1.0), 1e-6);
  EXPECT_LE(e.residual, 1e-9);
}

TEST(Extrapolation, RefusesTooFewLevelsAndBadSizes) {
  EXPECT_THROW(extrapolate({0.1, 0.05}, {1.0, 2.0}), InputError);
  EXPECT_THROW(extrapolate({0.1, 0.05, 0.02}, {1.0, 2.0}), InputError);
  EXPECT_THROW(extrapolate({0.1, 0.0, 0.02}, {1.0, 2.0, 3.0}), InputError);
  EXPECT_THROW(extrapolate({0.1, 0.05, 0.02}, {1.0, NAN, 3.0}), InputError);
}

}  // namespace
}  // namespace vorodg
