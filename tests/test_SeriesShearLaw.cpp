// The extrinsic cohesive law with the coupling's spring in series in shear (dg/SeriesShearLaw),
// on Petersson's concrete (sigma_c = 3.33 MPa, G = 124 J/m^2, beta = 1) with eps = 1e13 Pa/m:
//   - a purely normal opening is the law's own response;
//   - the tangent is the derivative of the traction (central differences, 1e-6 relative);
//   - the traction derives from the energy: along a loading path and back, the work of the
//     traction (fine trapezoids) equals the change of stored + dissipated energy (1e-6 relative);
//   - a face that opens while sheared meets the sticking branch (normal sqrt(sigma_c^2 - (eps
//     g_t / beta)^2), shear eps g_t) and its energy eps g_t^2 / 2 continuously as g_n -> 0+;
//   - the sliding stiffness never exceeds eps.
#include <gtest/gtest.h>

#include <cmath>

#include "dg/SeriesShearLaw.hpp"

namespace vorodg {
namespace {

constexpr double kStrength = 3.33e6, kEnergy = 124.0, kEps = 1e13;

const CohesiveLaw& law() {
  static const CohesiveLaw l(CohesiveParameters{kStrength, kEnergy, 1.0, "linear"});
  return l;
}

double energy(const Eigen::Vector2d& d, const CohesiveLaw::State& s) {
  return series_shear_stored_energy(law(), kEps, d, s) + law().dissipated_energy(s.max_opening);
}

TEST(SeriesShearLaw, PureOpeningIsTheLaw) {
  CohesiveLaw::State a, b;
  const Eigen::Vector2d d(1e-5, 0.0);
  const SeriesShearResponse r = series_shear_respond(law(), kEps, d, a);
  const CohesiveLaw::Response plain = law().respond(d, b);
  EXPECT_LT((r.traction - plain.traction).norm(), 1e-9 * kStrength);
  EXPECT_DOUBLE_EQ(a.max_opening, b.max_opening);
}

TEST(SeriesShearLaw, TangentIsTheDerivative) {
  const double dc = law().critical_opening();
  for (const Eigen::Vector2d& d :
       {Eigen::Vector2d(0.2 * dc, 0.1 * dc), Eigen::Vector2d(0.05 * dc, -0.3 * dc),
        Eigen::Vector2d(-0.1 * dc, 0.2 * dc)}) {
    for (bool unloading : {false, true}) {
      CohesiveLaw::State start;
      if (unloading) start.max_opening = 1.5 * std::hypot(std::max(d[0], 0.0), d[1]);
      CohesiveLaw::State s = start;
      const SeriesShearResponse r = series_shear_respond(law(), kEps, d, s);
      for (int j = 0; j < 2; ++j) {
        const double h = 1e-7 * dc;
        Eigen::Vector2d dp = d, dm = d;
        dp[j] += h, dm[j] -= h;
        CohesiveLaw::State sp = start, sm = start;
        const Eigen::Vector2d column = (series_shear_respond(law(), kEps, dp, sp).traction -
                                        series_shear_respond(law(), kEps, dm, sm).traction) /
                                       (2 * h);
        EXPECT_LT((column - r.tangent.col(j)).norm(), 1e-6 * (column.norm() + kStrength / dc))
            << "opening " << d.transpose() << (unloading ? " unloading" : " loading") << ", column "
            << j << ": " << column.transpose() << " vs " << r.tangent.col(j).transpose();
      }
    }
  }
}

TEST(SeriesShearLaw, TractionDerivesFromTheEnergy) {
  const double dc = law().critical_opening();
  const Eigen::Vector2d a(0.0, 0.0), b(0.3 * dc, 0.4 * dc), c(0.1 * dc, -0.1 * dc);
  CohesiveLaw::State s;
  s.max_opening = 1e-12 * dc;  // opened: the law's branch, not the sticking one
  double work = 0.0;
  Eigen::Vector2d d = Eigen::Vector2d(1e-12 * dc, 0.0), tau = Eigen::Vector2d::Zero();
  {
    CohesiveLaw::State t = s;
    tau = series_shear_respond(law(), kEps, d, t).traction;
    s = t;
  }
  const double start = energy(d, s);
  const int n = 20000;
  for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, c}}) {
    for (int k = 1; k <= n; ++k) {
      const Eigen::Vector2d next = from + (to - from) * (double(k) / n);
      const Eigen::Vector2d t = series_shear_respond(law(), kEps, next, s).traction;
      work += 0.5 * (tau + t).dot(next - d);
      d = next, tau = t;
    }
  }
  EXPECT_NEAR(work, energy(d, s) - start, 1e-6 * kEnergy) << "work " << work;
}

TEST(SeriesShearLaw, MeetsTheStickingBranchAsTheFaceOpens) {
  const double gt =
      0.2 * kStrength / kEps;  // a shear the sticking branch carries, eps g_t < sigma_c
  CohesiveLaw::State s;
  const Eigen::Vector2d d(1e-9 * kStrength / kEps, gt);
  const SeriesShearResponse r = series_shear_respond(law(), kEps, d, s);
  // The sticking branch's normal traction under this shear: what the envelope leaves beside it.
  const double sticking = std::sqrt(kStrength * kStrength - kEps * gt * kEps * gt);
  EXPECT_NEAR(r.traction[0], sticking, 1e-6 * kStrength);
  EXPECT_NEAR(r.traction[1], kEps * gt, 1e-6 * kStrength);
  EXPECT_NEAR(
      series_shear_stored_energy(law(), kEps, d, s) + law().dissipated_energy(s.max_opening),
      0.5 * kEps * gt * gt, 1e-6 * kStrength * gt);
}

TEST(SeriesShearLaw, SlidingNeverStifferThanTheSpring) {
  const double dc = law().critical_opening();
  for (double gt : {1e-9 * dc, 1e-4 * dc, 0.1 * dc, 0.9 * dc}) {
    CohesiveLaw::State s;
    const SeriesShearResponse r =
        series_shear_respond(law(), kEps, Eigen::Vector2d(1e-3 * dc, gt), s);
    EXPECT_LE(r.tangent(1, 1), kEps * (1 + 1e-12)) << gt;
    EXPECT_LE(std::abs(r.traction[1]), kEps * gt * (1 + 1e-12)) << gt;
  }
}

}  // namespace
}  // namespace vorodg
