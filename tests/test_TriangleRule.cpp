// Quadrature rules (core/quadrature/TriangleRule): the 1-, 3-, 6- and 7-point triangle rules
// and the two-point Gauss segment rule. Weights sum to one, points lie inside the triangle,
// every monomial up to the advertised degree is integrated exactly and at least one monomial of
// the next degree is not (so the advertised degree is sharp), other point counts are rejected.
// (The fan quadrature of whole cells is tested in test_ElementTable.)
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "core/quadrature/TriangleRule.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

constexpr int kCounts[] = {1, 3, 6, 7};

double factorial(int n) {
  double f = 1.0;
  for (int i = 2; i <= n; ++i) f *= i;
  return f;
}

/// Mean of x^a y^b over the reference triangle (0,0), (1,0), (0,1): 2 a! b! / (a + b + 2)!.
double exact_mean(int a, int b) {
  return 2.0 * factorial(a) * factorial(b) / factorial(a + b + 2);
}

/// The rule's estimate of the same mean (points mapped with x = l1, y = l2).
double rule_mean(const TriangleRule& rule, int a, int b) {
  double s = 0.0;
  for (int q = 0; q < rule.size(); ++q)
    s += rule.weights[q] * std::pow(rule.bary[q][1], a) * std::pow(rule.bary[q][2], b);
  return s;
}

TEST(TriangleRule, AdvertisedDegreesAndSizes) {
  EXPECT_EQ(triangle_rule(1).degree, 1);
  EXPECT_EQ(triangle_rule(3).degree, 2);
  EXPECT_EQ(triangle_rule(6).degree, 4);
  EXPECT_EQ(triangle_rule(7).degree, 5);
  for (int p : kCounts) {
    const TriangleRule& r = triangle_rule(p);
    EXPECT_EQ(r.size(), p);
    EXPECT_EQ(static_cast<int>(r.bary.size()), p);
    EXPECT_EQ(static_cast<int>(r.weights.size()), p);
    EXPECT_EQ(&triangle_rule(p), &r) << "rules are cached singletons";
  }
}

TEST(TriangleRule, WeightsSumToOneAndPointsAreInterior) {
  for (int p : kCounts) {
    const TriangleRule& r = triangle_rule(p);
    double sum = 0.0;
    for (int q = 0; q < r.size(); ++q) {
      sum += r.weights[q];
      EXPECT_GT(r.weights[q], 0.0) << p << "-point rule, point " << q;
      EXPECT_NEAR(r.bary[q].sum(), 1.0, 1e-15) << p << "-point rule, point " << q;
      for (int i = 0; i < 3; ++i)
        EXPECT_GT(r.bary[q][i], 0.0) << p << "-point rule, point " << q << " is not interior";
    }
    EXPECT_NEAR(sum, 1.0, 1e-14) << p << "-point rule";
  }
}

TEST(TriangleRule, ExactUpToItsDegreeAndNotBeyond) {
  for (int p : kCounts) {
    const TriangleRule& r = triangle_rule(p);
    for (int deg = 0; deg <= r.degree; ++deg)
      for (int a = 0; a <= deg; ++a) {
        const int b = deg - a;
        const double exact = exact_mean(a, b);
        EXPECT_NEAR(rule_mean(r, a, b), exact, 1e-13 * exact)
            << p << "-point rule, monomial x^" << a << " y^" << b;
      }
    // One degree higher: some monomial must be integrated with an error far above round-off.
    double worst = 0.0;
    const int deg = r.degree + 1;
    for (int a = 0; a <= deg; ++a) {
      const double exact = exact_mean(a, deg - a);
      worst = std::max(worst, std::abs(rule_mean(r, a, deg - a) - exact) / exact);
    }
    EXPECT_GT(worst, 1e-6) << p << "-point rule looks exact at degree " << deg
                           << ": its advertised degree is not sharp";
    std::cout << "[ rule ] " << p << "-point: largest relative error at degree " << deg << " = "
              << worst << "\n";
  }
}

TEST(TriangleRule, SymmetricUnderPermutationOfVertices) {
  // A rule symmetric in the three vertices integrates x^a y^b and y^a x^b (and any permutation
  // of the barycentric coordinates) alike; check the point set is closed under permutation.
  for (int p : kCounts) {
    const TriangleRule& r = triangle_rule(p);
    for (int q = 0; q < r.size(); ++q) {
      const Eigen::Vector3d perm(r.bary[q][1], r.bary[q][2], r.bary[q][0]);
      bool found = false;
      for (int s = 0; s < r.size(); ++s)
        if ((r.bary[s] - perm).norm() < 1e-14 && std::abs(r.weights[s] - r.weights[q]) < 1e-15)
          found = true;
      EXPECT_TRUE(found) << p << "-point rule, point " << q << " has no rotated partner";
    }
  }
}

TEST(TriangleRule, OtherCountsThrowInputError) {
  for (int p : {-1, 0, 2, 4, 5, 8, 12})
    EXPECT_THROW(triangle_rule(p), InputError) << p << " points";
}

TEST(SegmentRule, GaussTwoPointOnUnitInterval) {
  const SegmentRule& g = gauss2_segment();
  EXPECT_NEAR(g.weights[0] + g.weights[1], 1.0, 1e-15);
  EXPECT_NEAR(g.t[0] + g.t[1], 1.0, 1e-15) << "points symmetric about 1/2";
  for (int i = 0; i < 2; ++i) {
    EXPECT_GT(g.t[i], 0.0);
    EXPECT_LT(g.t[i], 1.0);
  }
  for (int p = 0; p <= 3; ++p) {
    const double s = g.weights[0] * std::pow(g.t[0], p) + g.weights[1] * std::pow(g.t[1], p);
    EXPECT_NEAR(s, 1.0 / (p + 1), 1e-15) << "t^" << p;
  }
  const double s4 = g.weights[0] * std::pow(g.t[0], 4) + g.weights[1] * std::pow(g.t[1], 4);
  EXPECT_GT(std::abs(s4 - 0.2), 1e-4) << "two-point Gauss cannot be exact for t^4";
  EXPECT_EQ(&gauss2_segment(), &g);
}

}  // namespace
}  // namespace vorodg
