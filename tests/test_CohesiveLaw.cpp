// The cohesive law's closed forms: the area under each envelope is G, the work of any monotone
// separation path equals the dissipated plus the recoverable energy and reaches G at full
// separation whatever the mode mix, unloading returns to the origin without dissipating, a
// closed crack carries no normal traction, and the tangent is the derivative of the traction.
// Every closed form runs on the shipped envelopes and on a toy one registered in this file alone
// (one registration line, as a new softening law is added): a trilinear envelope keeping the
// area G.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/util/Errors.hpp"
#include "fracture/CohesiveLaw.hpp"
#include "fracture/SofteningLaws.hpp"

namespace vorodg {
namespace {

constexpr double kStrength = 3.33e6, kEnergy = 124.0;  // concrete: sigma_c [Pa], G [N/m]

// The toy: (0, sigma_c) -> (0.5 G / sigma_c, sigma_c / 2) -> (3 G / sigma_c, 0), area
// 0.375 G + 0.625 G = G (extrinsic only: it ignores delta_0).
const bool kToyRegistered = register_softening_law(
    {"toy-trilinear", "a test's toy", [](double sc, double g, double) {
       return std::vector<Eigen::Vector2d>{{0.5 * g / sc, 0.5 * sc}, {3.0 * g / sc, 0.0}};
     }});

CohesiveLaw law(std::string shape, double beta = 1.0) {
  return CohesiveLaw({kStrength, kEnergy, beta, shape});
}

/// Simpson on n panels: exact on each linear piece, every kink costs O(panel^2).
double area_under_envelope(const CohesiveLaw& l, int n) {
  const double h = l.critical_opening() / n;
  double area = 0.0;
  for (int i = 0; i < n; ++i)
    area +=
        h / 6.0 * (l.envelope(i * h) + 4.0 * l.envelope((i + 0.5) * h) + l.envelope((i + 1) * h));
  return area;
}

class CohesiveLawShapes : public ::testing::TestWithParam<std::string> {};

TEST_P(CohesiveLawShapes, TheAreaUnderTheEnvelopeIsTheFractureEnergy) {
  const CohesiveLaw l = law(GetParam());
  EXPECT_DOUBLE_EQ(l.envelope(0.0), kStrength);
  EXPECT_EQ(l.envelope(l.critical_opening()), 0.0);
  EXPECT_EQ(l.envelope(2.0 * l.critical_opening()), 0.0);
  EXPECT_NEAR(area_under_envelope(l, 200000), kEnergy, 1e-9 * kEnergy);
  EXPECT_DOUBLE_EQ(l.dissipated_energy(l.critical_opening()), kEnergy);
}

TEST_P(CohesiveLawShapes, WorkOfAnyProportionalPathIsDissipatedPlusRecoverable) {
  // For every mode mix the work t . d(opening) along a straight path equals the area under the
  // envelope in the effective opening: dissipated + what unloading would give back, and G at
  // full separation.
  for (const double beta : {0.0, 0.5, 1.0, 2.0})
    for (const double angle : {0.0, 0.3, 1.0, 1.5}) {
      const CohesiveLaw l = law(GetParam(), beta);
      const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
      const double effective = std::hypot(direction[0], beta * direction[1]);
      if (effective == 0.0) continue;  // pure sliding with beta = 0: no effective opening
      const double reach = 1.2 * l.critical_opening() / effective;
      CohesiveLaw::State state;
      double work = 0.0;
      Eigen::Vector2d previous = Eigen::Vector2d::Zero(), t_previous(0.0, 0.0);
      const int steps = 100000;
      for (int i = 1; i <= steps; ++i) {
        const Eigen::Vector2d opening = (reach * i / steps) * direction;
        const Eigen::Vector2d t = l.respond(opening, state).traction;
        if (i > 1) work += 0.5 * (t + t_previous).dot(opening - previous);  // trapezoids
        previous = opening;
        t_previous = t;
        if (i == steps / 2) {  // half way: not yet separated
          const double d = state.max_opening;
          const double stored = 0.5 * l.envelope(d) * d;
          // The first step's work (from 0 to the first point, where T jumps from sigma_c) is
          // left out on purpose: add it exactly.
          const double first = (reach / steps) * effective;
          const double expected = l.dissipated_energy(d) + stored;
          const double measured = work + 0.5 * (kStrength + l.envelope(first)) * first;
          EXPECT_NEAR(measured, expected, 1e-6 * kEnergy) << beta << " " << angle;
        }
      }
      const double first = (reach / steps) * effective;
      work += 0.5 * (kStrength + l.envelope(first)) * first;
      EXPECT_NEAR(work, kEnergy, 1e-6 * kEnergy) << "beta " << beta << ", angle " << angle;
    }
}

TEST_P(CohesiveLawShapes, UnloadingGoesToTheOriginAndReloadingRetracesIt) {
  const CohesiveLaw l = law(GetParam());
  CohesiveLaw::State state;
  const double d1 = 0.3 * l.critical_opening();
  const auto at_max = l.respond({d1, 0.0}, state);
  EXPECT_TRUE(at_max.loading);
  const double dissipated = l.dissipated_energy(state.max_opening);
  const auto half = l.respond({0.5 * d1, 0.0}, state);
  EXPECT_FALSE(half.loading);
  EXPECT_NEAR(half.traction[0], 0.5 * at_max.traction[0], 1e-12 * kStrength);
  EXPECT_DOUBLE_EQ(state.max_opening, d1);
  const auto back = l.respond({d1, 0.0}, state);
  EXPECT_NEAR(back.traction[0], at_max.traction[0], 1e-12 * kStrength);
  EXPECT_DOUBLE_EQ(l.dissipated_energy(state.max_opening), dissipated);
  const auto zero = l.respond({0.0, 0.0}, state);
  EXPECT_EQ(zero.traction.norm(), 0.0);
}

TEST_P(CohesiveLawShapes, AClosedCrackCarriesNoNormalTraction) {
  const CohesiveLaw l = law(GetParam(), 1.0);
  CohesiveLaw::State state;
  const double d = 0.2 * l.critical_opening();
  const auto r = l.respond({-d, d}, state);  // overclosed and sliding
  EXPECT_EQ(r.traction[0], 0.0);
  EXPECT_NEAR(r.traction[1], l.envelope(d), 1e-12 * kStrength);  // the shear still softens
  EXPECT_EQ(r.tangent(0, 0), 0.0);
  EXPECT_EQ(r.tangent(0, 1), 0.0);
}

TEST_P(CohesiveLawShapes, TheTangentIsTheTractionsDerivative) {
  for (const double beta : {0.5, 1.0, 2.0})
    for (const double fraction : {0.1, 0.5, 0.9}) {  // both bilinear pieces
      const CohesiveLaw l = law(GetParam(), beta);
      const Eigen::Vector2d opening = fraction * l.critical_opening() * Eigen::Vector2d(0.8, 0.35) /
                                      std::hypot(0.8, 0.35 * beta);
      for (const bool unloading : {false, true}) {
        CohesiveLaw::State base;
        if (unloading) base.max_opening = 1.5 * fraction * l.critical_opening();
        CohesiveLaw::State probe = base;
        const Eigen::Matrix2d K = l.respond(opening, probe).tangent;
        const double h = 1e-7 * opening.norm();
        for (int j = 0; j < 2; ++j) {
          CohesiveLaw::State plus = base, minus = base;
          const Eigen::Vector2d e = Eigen::Vector2d::Unit(j) * h;
          // Forward-only differences on the loading branch (a step back would unload).
          const Eigen::Vector2d column =
              unloading
                  ? (l.respond(opening + e, plus).traction -
                     l.respond(opening - e, minus).traction) /
                        (2 * h)
                  : (l.respond(opening + e, plus).traction - l.respond(opening, minus).traction) /
                        h;
          EXPECT_NEAR((K.col(j) - column).norm(), 0.0, 1e-5 * K.norm())
              << "beta " << beta << ", " << fraction << " delta_c, unloading " << unloading;
        }
      }
    }
}

INSTANTIATE_TEST_SUITE_P(Shapes, CohesiveLawShapes,
                         ::testing::Values(std::string("linear"), std::string("bilinear"),
                                           std::string("toy-trilinear")),
                         [](const auto& info) {
                           std::string name = info.param;  // a test name takes no '-'
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(CohesiveLaw, BilinearKinksAtAThirdOfTheStrength) {
  const CohesiveLaw l = law("bilinear");
  EXPECT_NEAR(l.envelope(0.8 * kEnergy / kStrength), kStrength / 3.0, 1e-9 * kStrength);
  EXPECT_NEAR(l.critical_opening(), 3.6 * kEnergy / kStrength, 1e-15);
  EXPECT_NEAR(law("linear").critical_opening(), 2.0 * kEnergy / kStrength, 1e-15);
}

class IntrinsicLaw : public ::testing::TestWithParam<std::string> {};

TEST_P(IntrinsicLaw, ElasticUpToThePeakThenSoftensWithTheSameArea) {
  const double k0 = 1e3 * kStrength / (kEnergy / kStrength);  // peak at 1e-3 G / sigma_c
  const CohesiveLaw l({kStrength, kEnergy, 1.0, GetParam(), k0});
  const double d0 = kStrength / k0;
  EXPECT_EQ(l.envelope(0.0), 0.0);
  EXPECT_NEAR(l.envelope(0.5 * d0), 0.5 * kStrength, 1e-12 * kStrength);
  EXPECT_NEAR(l.envelope(d0), kStrength, 1e-9 * kStrength);
  // The elastic branch stores and gives back: nothing is dissipated before the peak.
  EXPECT_EQ(l.dissipated_energy(0.9 * d0), 0.0);
  // The area under the whole envelope is still G.
  EXPECT_NEAR(area_under_envelope(l, 400000), kEnergy, 1e-8 * kEnergy);
  EXPECT_DOUBLE_EQ(l.dissipated_energy(l.critical_opening()), kEnergy);
  // At zero opening the tangent is the initial stiffness in both directions (beta = 1).
  CohesiveLaw::State state;
  const auto r = l.respond(Eigen::Vector2d::Zero(), state);
  EXPECT_EQ(r.traction.norm(), 0.0);
  EXPECT_DOUBLE_EQ(r.tangent(1, 1), k0);
  EXPECT_EQ(r.tangent(0, 0), 0.0);  // closed: the normal stiffness is contact's
}

INSTANTIATE_TEST_SUITE_P(Shapes, IntrinsicLaw,
                         ::testing::Values(std::string("linear"), std::string("bilinear")),
                         [](const auto& info) { return info.param; });

TEST(CohesiveLaw, RefusesBadParametersAndNonFiniteOpenings) {
  // An intrinsic law so soft that its peak comes after the critical opening.
  EXPECT_THROW(CohesiveLaw({kStrength, kEnergy, 1.0, "linear", 1.0}), InputError);
  EXPECT_THROW(CohesiveLaw({0.0, kEnergy, 1.0, "linear"}), InputError);
  EXPECT_THROW(CohesiveLaw({kStrength, -1.0, 1.0, "linear"}), InputError);
  EXPECT_THROW(CohesiveLaw({kStrength, kEnergy, -0.1, "linear"}), InputError);
  EXPECT_THROW(CohesiveLaw({NAN, kEnergy, 1.0, "linear"}), InputError);
  EXPECT_THROW(CohesiveLaw({kStrength, kEnergy, 1.0, "no-such-softening"}), InputError);
  EXPECT_TRUE(kToyRegistered);
  EXPECT_THROW(register_softening_law({"linear", "again", nullptr}), InputError);
  try {
    CohesiveLaw({kStrength, -1.0, 1.0, "linear"});
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("fracture_energy"), std::string::npos) << e.what();
  }
  CohesiveLaw::State state;
  EXPECT_THROW(law("linear").respond({NAN, 0.0}, state), NumericalError);
}

}  // namespace
}  // namespace vorodg
