// The Mohr-Coulomb criterion with tensile cutoff on its closed-form boundary: pure tension fails
// at the cutoff, pure shear at the cohesion, compression adds mu |sigma| to the shear capacity.
#include <gtest/gtest.h>

#include <cmath>

#include "core/util/Errors.hpp"
#include "fracture/MohrCoulomb.hpp"

namespace vorodg {
namespace {

// The report's column: c = sigma_o = 3.7 MPa, mu = 0.75.
const MohrCoulomb kCriterion({3.7e6, 0.75, 3.7e6});
constexpr double kTol = 1e-12;

TEST(MohrCoulomb, TensionFailsAtTheCutoff) {
  EXPECT_NEAR(kCriterion.utilization(3.7e6, 0.0), 1.0, kTol);
  EXPECT_TRUE(kCriterion.fails(3.7e6, 0.0));
  EXPECT_FALSE(kCriterion.fails(3.7e6 * (1 - 1e-9), 0.0));
}

TEST(MohrCoulomb, ShearFailsAtTheCohesionPlusFrictionTimesCompression) {
  EXPECT_NEAR(kCriterion.utilization(0.0, 3.7e6), 1.0, kTol);
  EXPECT_NEAR(kCriterion.utilization(0.0, -3.7e6), 1.0, kTol);  // the sign of tau is irrelevant
  const double sigma = -2.0e6;                                  // compression
  const double limit = 3.7e6 + 0.75 * 2.0e6;
  EXPECT_NEAR(kCriterion.utilization(sigma, limit), 1.0, kTol);
  EXPECT_FALSE(kCriterion.fails(sigma, limit * (1 - 1e-9)));
  EXPECT_TRUE(kCriterion.fails(sigma, limit * (1 + 1e-9)));
}

TEST(MohrCoulomb, TensionLowersTheShearCapacityAndEventuallyRemovesIt) {
  // Between 0 and the cutoff the shear limit falls linearly; a tension at which c - mu sigma
  // would vanish lies beyond the cutoff here, and the utilization stays finite below it.
  EXPECT_NEAR(kCriterion.utilization(1.0e6, 3.7e6 - 0.75e6), 1.0, kTol);
  const MohrCoulomb frictional({1.0, 2.0, 10.0});  // c / mu = 0.5 < sigma_o
  EXPECT_TRUE(std::isinf(frictional.utilization(0.6, 0.0)));
  EXPECT_TRUE(frictional.fails(0.6, 0.0));
}

TEST(MohrCoulomb, RefusesBadParametersAndNonFiniteTractions) {
  EXPECT_THROW(MohrCoulomb({0.0, 0.5, 1.0}), InputError);
  EXPECT_THROW(MohrCoulomb({1.0, -0.5, 1.0}), InputError);
  EXPECT_THROW(MohrCoulomb({1.0, 0.5, 0.0}), InputError);
  EXPECT_THROW(kCriterion.utilization(NAN, 0.0), NumericalError);
}

}  // namespace
}  // namespace vorodg
