// The random material field (core/random): its correlations against their closed forms, and
// the sampled field against its specification over 200 realizations (fixed seeds):
//   - mean 0 and variance 1 at a point, and the correlation at lags l/2, l and 2l, each within
//     three standard errors of the specification (the standard error of a sample correlation of
//     n pairs is (1 - rho^2) / sqrt(n); of a sample variance of a normal, sqrt(2 / (n - 1)));
//   - the marginal (uniform +-5 %, Weibull) passes Kolmogorov-Smirnov at 5 % as often as a
//     correct generator does (20 sets of 200), and on all 4000 values together;
//   - one seed gives one field, whatever is asked of it; a polygon's mean is the field's mean
//     over it (exact for a field that is linear in space, and close for the sampled one).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/random/FieldMarginal.hpp"
#include "core/random/GaussianRandomField.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

const Rectangle kSquare(0.0, 0.0, 1.0, 1.0);
constexpr int kRealizations = 200;

FieldCovariance matern(double nu, double length) {
  return {CovarianceKind::matern, length, nu};
}

TEST(FieldCovariance, MaternMeetsItsHalfIntegerClosedForms) {
  const double l = 0.3;
  for (double r : {0.0, 0.01, 0.1, 0.3, 0.7, 2.0}) {
    const double x = r / l;
    EXPECT_NEAR(matern(0.5, l)(r), std::exp(-x), 1e-13) << r;
    const double a = std::sqrt(3.0) * x, b = std::sqrt(5.0) * x;
    EXPECT_NEAR(matern(1.5, l)(r), (1.0 + a) * std::exp(-a), 1e-13) << r;
    EXPECT_NEAR(matern(2.5, l)(r), (1.0 + b + b * b / 3.0) * std::exp(-b), 1e-13) << r;
    const FieldCovariance squared{CovarianceKind::squared_exponential, l};
    EXPECT_NEAR(squared(r), std::exp(-0.5 * x * x), 1e-15);
  }
  // A large smoothness approaches the squared exponential.
  EXPECT_NEAR(matern(60.0, l)(l), std::exp(-0.5), 5e-3);
}

TEST(FieldCovariance, BadSpecificationsAreRefused) {
  EXPECT_THROW(matern(0.0, 1.0).check(), InputError);
  EXPECT_THROW(matern(1.5, -1.0).check(), InputError);
  EXPECT_THROW(covariance_kind("gaussian"), InputError);
  EXPECT_EQ(covariance_kind(covariance_name(CovarianceKind::matern)), CovarianceKind::matern);
  EXPECT_THROW((FieldMarginal{MarginalKind::uniform, 1.0}.check()), InputError);
  EXPECT_THROW(marginal_kind("normal"), InputError);
  EXPECT_THROW(GaussianRandomField(Rectangle(0, 0, 1, 0), matern(1.5, 0.1), 1), InputError);
}

/// g(x0) and g(x0 + lag) over the realizations (seeds 1 .. n).
struct Pairs {
  std::vector<double> at, away;
};

Pairs sample_pairs(const FieldCovariance& c, const Point& lag) {
  const Point x0(0.3, 0.5);  // a grid node for l = 0.1 (spacing l / 8)
  const CirculantEmbedding embedding(kSquare, c);
  Pairs p;
  for (int seed = 1; seed <= kRealizations; ++seed) {
    const GaussianRandomField field(embedding, static_cast<std::uint64_t>(seed));
    p.at.push_back(field.value(x0));
    p.away.push_back(field.value(x0 + lag));
  }
  return p;
}

double mean(const std::vector<double>& x) {
  double s = 0.0;
  for (double v : x) s += v;
  return s / static_cast<double>(x.size());
}

double correlation(const Pairs& p) {
  const double ma = mean(p.at), mb = mean(p.away);
  double ab = 0.0, aa = 0.0, bb = 0.0;
  for (std::size_t i = 0; i < p.at.size(); ++i) {
    ab += (p.at[i] - ma) * (p.away[i] - mb);
    aa += (p.at[i] - ma) * (p.at[i] - ma);
    bb += (p.away[i] - mb) * (p.away[i] - mb);
  }
  return ab / std::sqrt(aa * bb);
}

TEST(GaussianRandomField, MeanVarianceAndCorrelationsMatchTheSpecification) {
  const double n = kRealizations, l = 0.1;
  for (const FieldCovariance& c :
       {FieldCovariance{CovarianceKind::squared_exponential, l}, matern(1.5, l)}) {
    for (double lag : {0.5 * l, l, 2.0 * l}) {
      const Pairs p = sample_pairs(c, Point(lag, 0.0));
      const double m = mean(p.at);
      double variance = 0.0;
      for (double v : p.at) variance += (v - m) * (v - m) / (n - 1.0);
      const double rho = c(lag), r = correlation(p);
      std::printf("%s, lag %.2f l: mean %+.3f, variance %.3f, correlation %.3f (specified %.3f)\n",
                  covariance_name(c.kind).c_str(), lag / l, m, variance, r, rho);
      EXPECT_NEAR(m, 0.0, 3.0 / std::sqrt(n));
      EXPECT_NEAR(variance, 1.0, 3.0 * std::sqrt(2.0 / (n - 1.0)));
      EXPECT_NEAR(r, rho, 3.0 * (1.0 - rho * rho) / std::sqrt(n));
    }
  }
}

/// The one-sample Kolmogorov-Smirnov distance of x from the CDF F.
template <class Cdf>
double ks_distance(std::vector<double> x, Cdf F) {
  std::sort(x.begin(), x.end());
  const double n = static_cast<double>(x.size());
  double d = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double f = F(x[i]);
    d = std::max({d, f - static_cast<double>(i) / n, static_cast<double>(i + 1) / n - f});
  }
  return d;
}

TEST(GaussianRandomField, MarginalsPassKolmogorovSmirnovAtFivePerCent) {
  // At a fixed point the realizations' values are independent, so a test at 5 % rejects one set
  // of 200 in twenty whatever the seeds: a single set can neither pass nor fail the generator.
  // So: 20 disjoint sets of 200 realizations (seeds 1 .. 4000, on a small domain), each tested
  // at 5 %; at most 4 rejections (1 expected; 5 or more has probability 0.3 % for a correct
  // generator), and all 4000 values together pass at 5 %.
  const Rectangle small(0.0, 0.0, 0.2, 0.2);
  const FieldCovariance c = matern(1.5, 0.1);
  const FieldMarginal uniform{MarginalKind::uniform, 0.05},
      weibull{MarginalKind::weibull, 0.0, 8.0};
  const CirculantEmbedding embedding(small, c);
  std::printf("a %d x %d grid, embedded in %d x %d\n", embedding.nodes_x(), embedding.nodes_y(),
              embedding.embedding_x(), embedding.embedding_y());
  constexpr int kSets = 20;
  std::vector<double> all_uniform, all_weibull;
  int rejected_uniform = 0, rejected_weibull = 0;
  const double critical = 1.358 / std::sqrt(double(kRealizations));
  for (int set = 0; set < kSets; ++set) {
    std::vector<double> u, w;
    for (int k = 1; k <= kRealizations; ++k) {
      const GaussianRandomField field(embedding, std::uint64_t(set * kRealizations + k));
      const double g = field.value(Point(0.1, 0.1));
      u.push_back(uniform(g));
      w.push_back(weibull(g));
    }
    rejected_uniform += ks_distance(u, [&](double x) { return uniform.cdf(x); }) > critical;
    rejected_weibull += ks_distance(w, [&](double x) { return weibull.cdf(x); }) > critical;
    all_uniform.insert(all_uniform.end(), u.begin(), u.end());
    all_weibull.insert(all_weibull.end(), w.begin(), w.end());
  }
  const double pooled_critical = 1.358 / std::sqrt(double(all_uniform.size()));
  const double du = ks_distance(all_uniform, [&](double x) { return uniform.cdf(x); });
  const double dw = ks_distance(all_weibull, [&](double x) { return weibull.cdf(x); });
  std::printf(
      "KS at 5 %% on %d sets of %d: uniform rejected %d, Weibull %d; all %zu values: "
      "%.4f and %.4f against %.4f\n",
      kSets, kRealizations, rejected_uniform, rejected_weibull, all_uniform.size(), du, dw,
      pooled_critical);
  EXPECT_LE(rejected_uniform, 4);
  EXPECT_LE(rejected_weibull, 4);
  EXPECT_LT(du, pooled_critical);
  EXPECT_LT(dw, pooled_critical);
  const auto [lo, hi] = std::minmax_element(all_uniform.begin(), all_uniform.end());
  EXPECT_GE(*lo, 0.95);
  EXPECT_LE(*hi, 1.05);
}

TEST(GaussianRandomField, OneSeedIsOneFieldAndAPolygonGetsItsMean) {
  const FieldCovariance c = matern(1.5, 0.1);
  const GaussianRandomField a(kSquare, c, 7), b(kSquare, c, 7), other(kSquare, c, 8);
  EXPECT_EQ(a.spacing(), 0.1 / 8.0);
  EXPECT_GE((a.nodes_x() - 1) * a.spacing(), 1.0 - 1e-12);
  const CirculantEmbedding embedding(kSquare, c);
  std::printf("a %d x %d grid, embedded in %d x %d\n", embedding.nodes_x(), embedding.nodes_y(),
              embedding.embedding_x(), embedding.embedding_y());
  EXPECT_LE(embedding.clipped(), 1e-10);
  EXPECT_GE(embedding.embedding_x(), 2 * (embedding.nodes_x() - 1));
  EXPECT_EQ(GaussianRandomField(embedding, 7).value(Point(0.31, 0.77)), a.value(Point(0.31, 0.77)));
  for (const Point& x : {Point(0.0, 0.0), Point(0.31, 0.77), Point(1.0, 1.0)}) {
    EXPECT_EQ(a.value(x), b.value(x));
    EXPECT_NE(a.value(x), other.value(x));
  }
  EXPECT_THROW(a.value(Point(1.1, 0.5)), InputError);
  // A square of one grid cell: the mean of the bilinear interpolant is the mean of its corners.
  const double s = a.spacing();
  const std::vector<Point> cell{Point(4 * s, 8 * s), Point(5 * s, 8 * s), Point(5 * s, 9 * s),
                                Point(4 * s, 9 * s)};
  double corners = 0.0;
  for (const Point& x : cell) corners += a.value(x) / 4.0;
  EXPECT_NEAR(a.mean_over(cell), corners, 1e-14);
  // A polygon many cells wide: its mean is that of the field's values inside it.
  const std::vector<Point> wide{Point(0.2, 0.2), Point(0.6, 0.25), Point(0.5, 0.7),
                                Point(0.25, 0.6)};
  auto inside = [&](const Point& x) {  // the polygon is convex and counter-clockwise
    for (std::size_t k = 0; k < wide.size(); ++k) {
      const Point e = wide[(k + 1) % wide.size()] - wide[k], d = x - wide[k];
      if (e.x() * d.y() - e.y() * d.x() < 0.0) return false;
    }
    return true;
  };
  double sum = 0.0;
  int count = 0;
  for (int i = 0; i < 800; ++i)
    for (int j = 0; j < 800; ++j) {
      const Point x(0.2 + 0.4 * (i + 0.5) / 800.0, 0.2 + 0.5 * (j + 0.5) / 800.0);
      if (inside(x)) sum += a.value(x), ++count;
    }
  std::printf("mean over a wide polygon: %.5f, over %d points inside it: %.5f\n", a.mean_over(wide),
              count, sum / count);
  EXPECT_NEAR(a.mean_over(wide), sum / count, 2e-3);
  EXPECT_THROW(a.mean_over(std::vector<Point>{Point(0, 0), Point(1, 1)}), InputError);
  EXPECT_THROW(a.mean_over(std::vector<Point>{Point(0, 0), Point(0.5, 0.5), Point(1, 1)}),
               InputError);
}

}  // namespace
}  // namespace vorodg
