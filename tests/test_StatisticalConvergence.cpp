// The statistical-convergence analysis and its report (verification/report/StatisticalConvergence,
// StatisticalVerdicts, StatisticalConvergenceReport) on synthetic levels whose answer is known:
// a quantity that converges at second order in h on coupled levels, one that grows like h^-2,
// one whose law and mean agree between levels while its realizations do not (the report's
// warning), and one too small a sample to decide. Fixed seeds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include "core/util/Errors.hpp"
#include "verification/harness/RecordFields.hpp"
#include "verification/harness/StatisticalReport.hpp"
#include "verification/report/SamplePlanner.hpp"
#include "verification/report/StatisticalConvergence.hpp"
#include "verification/report/StatisticalConvergenceReport.hpp"

namespace vorodg {
namespace {

const std::vector<double> kH = {0.4, 0.2, 0.1, 0.05};

/// Level k of realization i: `value(h, x_i, z_ik)` with x_i shared by every level (the coupled
/// random field) and z_ik the level's own (its mesh).
template <class Value>
std::vector<LevelSample> levels(std::size_t n, Value value, std::uint64_t seed = 1) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  std::vector<double> x(n);
  for (double& v : x) v = normal(rng);
  std::vector<LevelSample> out;
  for (std::size_t k = 0; k < kH.size(); ++k) {
    LevelSample l;
    l.h_avg = kH[k];
    for (std::size_t i = 0; i < n; ++i) {
      l.realization.push_back(static_cast<int>(i));
      l.value.push_back(value(kH[k], x[i], normal(rng), k));
    }
    out.push_back(l);
  }
  return out;
}

TEST(StatisticalConvergence, SecondOrderOnCoupledLevelsConvergesInEverySense) {
  // q = 10 + x + 20 h^2 (1 + z): E|D| and the mean's change fall four times per halving.
  StatisticalOptions o;
  o.coupled = true;
  const auto q = statistical_convergence(
      "peak",
      levels(400, [](double h, double x, double z,
                     std::size_t) { return 10.0 + x + 20.0 * h * h * (1.0 + 0.3 * z); }),
      o);
  ASSERT_EQ(q.steps.size(), 3u);
  EXPECT_EQ(q.in_distribution.verdict, Verdict::converges) << q.in_distribution.reason;
  EXPECT_EQ(q.of_mean.verdict, Verdict::converges) << q.of_mean.reason;
  EXPECT_EQ(q.in_mean.verdict, Verdict::converges) << q.in_mean.reason;
  EXPECT_EQ(q.in_probability.verdict, Verdict::converges) << q.in_probability.reason;
  // E|D| between the two coarsest levels: 20 (0.16 - 0.04) E|1 + 0.3 z'| ~ 2.4, h^2 per step.
  const double d0 = q.steps[0].coupled->mean_absolute.estimate;
  const double d1 = q.steps[1].coupled->mean_absolute.estimate;
  EXPECT_NEAR(std::log(d0 / d1) / std::log(2.0), 2.0, 0.15);
  EXPECT_NEAR(q.epsilon, 0.05 * 10.0, 0.05);  // 5 % of the finest mean, about 10
}

TEST(StatisticalConvergence, AQuantityGrowingLikeHToTheMinusTwoDoesNotConverge) {
  const auto q = statistical_convergence("fragments",
                                         levels(12, [](double h, double x, double z, std::size_t) {
                                           return 0.5 / (h * h) * (1.0 + 0.05 * x + 0.05 * z);
                                         }));
  EXPECT_EQ(q.in_distribution.verdict, Verdict::does_not_converge) << q.in_distribution.reason;
  EXPECT_EQ(q.of_mean.verdict, Verdict::does_not_converge) << q.of_mean.reason;
  ASSERT_TRUE(q.trend.has_value());
  EXPECT_NEAR(*q.trend, -2.0, 0.05);  // the levels' means scatter by 2 %: the slope by 0.015
  EXPECT_EQ(q.in_mean.verdict, Verdict::not_applicable);  // independent levels: no pairs
  EXPECT_EQ(q.in_probability.verdict, Verdict::not_applicable);
}

TEST(StatisticalConvergence, OneLawAndOneMeanButRealizationsThatDoNotSettle) {
  // The report's warning: q = +-x alternating with the level. Same law at every level (KS does
  // not tell them apart), the mean does not move, yet |D| = 2|x| at every step.
  StatisticalOptions o;
  o.coupled = true;
  const auto q = statistical_convergence(
      "rotation",
      levels(400, [](double, double x, double, std::size_t k) { return k % 2 ? -x : x; }), o);
  EXPECT_EQ(q.in_distribution.verdict, Verdict::converges) << q.in_distribution.reason;
  EXPECT_NE(q.of_mean.verdict, Verdict::does_not_converge) << q.of_mean.reason;
  EXPECT_EQ(q.in_mean.verdict, Verdict::does_not_converge) << q.in_mean.reason;
  EXPECT_EQ(q.in_probability.verdict, Verdict::does_not_converge) << q.in_probability.reason;
  EXPECT_NEAR(q.steps.back().coupled->mean_absolute.estimate, 2.0 * std::sqrt(2.0 / M_PI), 0.15);
}

TEST(StatisticalConvergence, TwelveRealizationsCannotDecideAndSayHowManyWould) {
  const auto q = statistical_convergence(
      "largest fragment",
      levels(12, [](double, double, double z, std::size_t) { return 0.3 + 0.1 * z; }));
  EXPECT_EQ(q.in_distribution.verdict, Verdict::undecided) << q.in_distribution.reason;
  EXPECT_EQ(q.in_distribution.realizations, realizations_for_ks(0.1));
  EXPECT_EQ(q.of_mean.verdict, Verdict::undecided) << q.of_mean.reason;
  // The change's spread is sqrt(s_k^2 + s_k+1^2), about sqrt(2) 0.1 (the two sample deviations
  // of 12 values scatter by a fifth). To decide, the change's interval must fit inside +-eps
  // (eps = 5 % of 0.3), a half-width of eps - |change| (at least eps / 10), or, for a change
  // beyond eps, clear 0: a half-width of |change|.
  const auto sd = [](const std::vector<double>& v) {
    double m = 0.0, ss = 0.0;
    for (double x : v) m += x / static_cast<double>(v.size());
    for (double x : v) ss += (x - m) * (x - m);
    return std::sqrt(ss / static_cast<double>(v.size() - 1));
  };
  const LevelStep& finest = q.steps.back();
  EXPECT_NEAR(finest.change_std_dev, std::hypot(sd(q.levels[2].value), sd(q.levels[3].value)),
              1e-14);
  const double change = std::abs(finest.mean_change.estimate);
  const double half = change > q.epsilon ? change : std::max(q.epsilon - change, 0.1 * q.epsilon);
  EXPECT_EQ(q.of_mean.realizations, realizations_for_mean(finest.change_std_dev, half));
  EXPECT_GT(q.of_mean.realizations, 12u);
}

TEST(StatisticalConvergence, AQuantityHalfTheRunsMeasureAsksForTwiceTheRuns) {
  // Twelve values per level as above, but from 24 complete runs (a rear-strike time that half the
  // columns have): the planner's values and pairs are each twice as many runs.
  StatisticalOptions o;
  o.coupled = true;
  const auto spread = [](double, double, double z, std::size_t) { return 0.3 + 0.1 * z; };
  const auto all = statistical_convergence("strike time", levels(12, spread), o);
  auto half_measured = levels(12, spread);
  for (LevelSample& l : half_measured)
    for (int i = 0; i < 24; ++i) l.complete.push_back(i);
  const auto q = statistical_convergence("strike time", half_measured, o);
  EXPECT_EQ(q.steps.back().measured_share, 0.5);
  EXPECT_EQ(q.steps.back().paired_share, 0.5);
  ASSERT_EQ(all.in_distribution.verdict, Verdict::undecided);
  EXPECT_EQ(q.in_distribution.realizations, 2 * all.in_distribution.realizations);
  ASSERT_EQ(all.of_mean.verdict, Verdict::undecided) << all.of_mean.reason;
  EXPECT_EQ(q.of_mean.realizations, 2 * all.of_mean.realizations);
  EXPECT_NE(q.of_mean.reason.find("50 % of the runs give one"), std::string::npos)
      << q.of_mean.reason;
  // A measured realization missing from the complete runs is refused.
  half_measured[1].complete = {0, 1, 2};
  EXPECT_THROW(statistical_convergence("strike time", half_measured, o), InputError);
}

TEST(StatisticalConvergence, AConstantQuantityConvergesInDistributionOnceTheSampleBoundsIt) {
  // A straight crack's tortuosity: 1 in every run. With n runs per level the laws can differ by
  // at most ln(2 / 0.05) / n = 3.69 / n at 95 %: 362 runs bound it by 0.0102 (< 0.1); 12 runs
  // by 0.31, and 37 would bound it by 0.1.
  const auto constant = [](double, double, double, std::size_t) { return 1.0; };
  const auto many = statistical_convergence("crack tortuosity", levels(362, constant));
  EXPECT_EQ(many.in_distribution.verdict, Verdict::converges) << many.in_distribution.reason;
  EXPECT_NE(many.in_distribution.reason.find("0.01"), std::string::npos)
      << many.in_distribution.reason;
  const auto few = statistical_convergence("crack tortuosity", levels(12, constant));
  EXPECT_EQ(few.in_distribution.verdict, Verdict::undecided) << few.in_distribution.reason;
  EXPECT_EQ(few.in_distribution.realizations, 37u);
  EXPECT_EQ(few.of_mean.verdict, Verdict::converges) << few.of_mean.reason;
  // Constant on one level only is not constant: the usual test decides.
  auto mixed = levels(362, constant);
  mixed[2].value[0] = 1.5;
  const auto q = statistical_convergence("crack tortuosity", mixed);
  EXPECT_EQ(q.in_distribution.reason.find("every realization"), std::string::npos);
}

LevelSample sample(double h, std::vector<int> realization, std::vector<double> value) {
  LevelSample l;
  l.h_avg = h;
  l.realization = std::move(realization);
  l.value = std::move(value);
  return l;
}

TEST(StatisticalConvergence, RefusesWhatItCannotAnalyse) {
  const LevelSample one = sample(0.1, {0, 1}, {1.0, 2.0});
  EXPECT_THROW(statistical_convergence("q", {one}), InputError);
  EXPECT_THROW(statistical_convergence("q", {one, sample(0.05, {0}, {1.0})}), InputError);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(statistical_convergence("q", {one, sample(0.05, {0, 1}, {1.0, nan})}), InputError);
}

TEST(StatisticalConvergenceReport, WritesEveryQuantityAndNumbersThatReadBack) {
  StatisticalOptions o;
  o.coupled = true;
  const std::vector<QuantityConvergence> qs = {
      statistical_convergence(
          "peak",
          levels(30, [](double h, double x, double z,
                        std::size_t) { return 10.0 + x + 20.0 * h * h * (1.0 + 0.3 * z); }),
          o),
      statistical_convergence(
          "count",
          levels(30, [](double h, double x, double, std::size_t) { return 1.0 / (h * h) + x; }),
          o)};
  const std::string md = statistical_convergence_md(qs, o);
  for (const char* part :
       {"## peak", "## count", "In distribution", "In probability", "E\\|D\\|^2 [interval]"})
    EXPECT_NE(md.find(part), std::string::npos) << part;
  const std::string csv = statistical_convergence_csv(qs);
  std::istringstream lines(csv);
  std::string header, row;
  std::getline(lines, header);
  EXPECT_NE(header.find("quantity"), std::string::npos);
  EXPECT_NE(header.find("E|D| low"), std::string::npos);
  int rows = 0;
  while (std::getline(lines, row)) ++rows;
  EXPECT_EQ(rows, 6);  // three pairs of levels per quantity
}

TEST(StatisticalReport, GroupsCompleteRecordsByMeshBlockAndLevel) {
  // Block "a": level 0 (h 0.2, 0.22) and level 1 (h 0.1, 0.12, one run incomplete, one NaN);
  // block "b": one level only (nothing to compare); "c": a level of one run (dropped).
  std::vector<nlohmann::json> records;
  const auto add = [&](const char* mesh, int level, int realization, double h, double q,
                       bool complete = true) {
    nlohmann::json r = {{"mesh", mesh},
                        {"level", level},
                        {"realization", realization},
                        {"h_avg", h},
                        {"complete", complete}};
    r["q"] = number_json(q);
    r["seconds"] = 1.5;
    records.push_back(r);
  };
  add("a", 0, 0, 0.2, 10.0);
  add("a", 0, 1, 0.22, 12.0);
  add("a", 1, 0, 0.1, 11.0);
  add("a", 1, 1, 0.12, 11.5);
  add("a", 1, 2, 0.1, 50.0, false);                               // incomplete: left out
  add("a", 1, 3, 0.1, std::numeric_limits<double>::quiet_NaN());  // not measured: left out
  add("b", 0, 0, 0.2, 1.0);
  add("b", 0, 1, 0.2, 2.0);
  add("c", 0, 0, 0.2, 1.0);
  add("c", 0, 1, 0.2, 2.0);
  add("c", 1, 0, 0.1, 1.0);
  StatisticalSettings settings;
  settings.quantities = {"q"};
  const std::vector<QuantityConvergence> q = statistical_convergence_of(records, settings);
  ASSERT_EQ(q.size(), 1u);
  EXPECT_EQ(q[0].name, "q");
  EXPECT_EQ(q[0].mesh, "a");
  ASSERT_EQ(q[0].levels.size(), 2u);
  EXPECT_NEAR(q[0].levels[0].h_avg, 0.21, 1e-15);
  // The level's h and cost are its complete runs' (the one not measured included), its values
  // the measured ones.
  EXPECT_NEAR(q[0].levels[1].h_avg, (0.1 + 0.12 + 0.1) / 3.0, 1e-15);
  EXPECT_EQ(q[0].levels[1].value, (std::vector<double>{11.0, 11.5}));
  EXPECT_EQ(q[0].levels[1].complete, (std::vector<int>{0, 1, 3}));
  EXPECT_EQ(q[0].levels[1].core_seconds, 4.5);  // three complete runs, 1.5 s each
  EXPECT_NEAR(q[0].steps[0].mean_change.estimate, 11.0 - 11.25, 1e-14);
}

}  // namespace
}  // namespace vorodg
