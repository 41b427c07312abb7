// The trade-off analysis on made-up runs (verification/kinds/tradeoff/TradeoffAnalysis), where
// every number is known in closed form: 4 levels x 3 realizations of four configurations,
//   - "clean":     L2 error 0.5 h^2, energy error h, time 2e-3 h^-2 s (error = 1e-3 / time);
//   - "crossing":  L2 error |h^2 - 19 h^3|, a signed error that crosses zero between h = 0.1 and
//                  0.05: very accurate at h = 0.05 (1.25e-4), worse again at 0.025 (3.3e-4);
//   - "short":     the clean errors but every run under min_seconds: no error-cost line;
//   - "failing":   the clean runs, one of which broke down.
// Checks: only "clean" is admitted; "crossing" is excluded for its rising error and its rate,
// each reason named; the front holds only clean's timed levels; the cost line has slope 1 and
// intercept log(0.5e-3) to round-off; the default targets are three decades down to the power of
// ten at or below the best finest error, and their predicted times and sizes follow the closed
// forms. The check's scene is the recommended configuration alone at the predicted size, and a
// check far beyond the study (over 10 times the finest level's cells) is refused with the reason.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "verification/kinds/tradeoff/TradeoffAnalysis.hpp"
#include "verification/kinds/tradeoff/TradeoffVerification.hpp"
#include "verification/static/StudyRunner.hpp"

namespace vorodg {
namespace {

const char* kScene = R"({
  "study": "trade-off",
  "meshes": [{"family": "rcp", "sizes": [0.2, 0.1, 0.05, 0.025], "realizations": 3}],
  "formulations": [{"name": "cg", "label": "clean"}, {"name": "cg", "label": "crossing"},
                   {"name": "cg", "label": "short"}, {"name": "cg", "label": "failing"}],
  "tradeoff": {"min_seconds": 0.5}
})";

/// A record whose metrics follow the closed forms of its configuration.
RunRecord made_up(const StudyRun& run) {
  const double h = run.size;
  RunRecord r{run, RunMetrics{}, ""};
  RunMetrics& m = *r.metrics;
  m.h_avg = h;
  m.dofs = static_cast<int>(4.0 / (h * h));
  m.l2_error = 0.5 * h * h;
  m.energy_error = h;
  m.seconds["solve"] = 2e-3 / (h * h);
  if (run.formulation_label == "crossing") m.l2_error = std::abs(h * h - 19 * h * h * h);
  if (run.formulation_label == "short") m.seconds["solve"] = 1e-4;
  if (run.formulation_label == "failing" && run.level == 2 && run.realization == 1) {
    r.metrics.reset();
    r.error = "made-up breakdown";
  }
  return r;
}

const TradeoffConfig& config(const TradeoffAnalysis& a, const std::string& variant) {
  for (const TradeoffConfig& c : a.configs)
    if (c.variant == variant) return c;
  throw std::runtime_error("no configuration " + variant);
}

bool has_reason(const TradeoffConfig& c, const std::string& words) {
  for (const std::string& reason : c.exclusions)
    if (reason.find(words) != std::string::npos) return true;
  return false;
}

TEST(TradeoffAnalysis, OnlyConvergingTimedConfigurationsStandOnTheFront) {
  const Scene scene = parse_scene(kScene, "made-up scene", {.tradeoff = true});
  std::vector<RunRecord> records;
  for (const StudyRun& run : expand_runs(scene)) records.push_back(made_up(run));
  const StudySummary summary = summarize_study(scene, records, nullptr);
  const TradeoffAnalysis a = analyse_tradeoff(scene, summary, records);
  ASSERT_EQ(a.configs.size(), 4u);

  for (const TradeoffConfig& c : a.configs)
    for (const std::string& reason : c.exclusions)
      std::printf("%s excluded: %s\n", c.variant.c_str(), reason.c_str());
  const TradeoffConfig& clean = config(a, "clean");
  EXPECT_TRUE(clean.admitted()) << clean.exclusions.front();
  const TradeoffConfig& crossing = config(a, "crossing");
  EXPECT_FALSE(crossing.admitted());
  EXPECT_TRUE(has_reason(crossing, "mean L2 error rises from level 2")) << crossing.exclusions[0];
  EXPECT_TRUE(has_reason(crossing, "L2 rate"));
  EXPECT_TRUE(has_reason(crossing, "between two levels"));  // a negative pair rate
  EXPECT_TRUE(has_reason(config(a, "short"), "0 of its levels take >= 0.5 s"));
  EXPECT_TRUE(has_reason(config(a, "failing"), "1 of 12 runs failed"));

  // Timed: levels whose median is >= 0.5 s, i.e. h <= sqrt(4e-3) (levels 2 and 3).
  int timed = 0;
  for (const TradeoffLevel& lv : clean.levels) timed += lv.timed;
  EXPECT_EQ(timed, 2);
  ASSERT_EQ(a.front.size(), 2u);
  for (const TradeoffPoint& p : a.front) EXPECT_EQ(p.config, &clean);

  // e = 0.5 h^2 and t = 2e-3 / h^2 give e = 1e-3 / t: slope 1, intercept log(1e-3).
  ASSERT_TRUE(clean.cost_fit);
  EXPECT_NEAR(clean.slope(), 1.0, 1e-10);
  EXPECT_NEAR(clean.cost_fit->intercept, std::log(1e-3), 1e-9);
  EXPECT_NEAR(clean.predicted_seconds(1e-5), 100.0, 100.0 * 1e-9);

  // Best finest error: 0.5 x 0.025^2 = 3.1e-4, so the targets are 1e-2, 1e-3 and 1e-4.
  ASSERT_EQ(a.targets.size(), 3u);
  EXPECT_NEAR(a.targets[0].error, 1e-2, 1e-14);
  EXPECT_NEAR(a.targets[2].error, 1e-4, 1e-16);
  for (const TradeoffTarget& t : a.targets) {
    ASSERT_EQ(t.config, &clean);
    EXPECT_NEAR(t.seconds, 1e-3 / t.error, 1e-9 * t.seconds);
    EXPECT_NEAR(t.size, std::sqrt(2 * t.error), 1e-9 * t.size);  // e = 0.5 size^2
  }
  // clean's timed errors span 3.1e-4 to 1.25e-3: 1e-3 inside, the others outside.
  EXPECT_TRUE(a.targets[0].extrapolated);
  EXPECT_FALSE(a.targets[1].extrapolated);
  EXPECT_TRUE(a.targets[2].extrapolated);
}

TEST(TradeoffAnalysis, TheCheckRunsTheSmallestTargetWithinReachOnly) {
  // The check of 1e-4 (clean: size sqrt(2e-4), 3.1 times the finest level's cells) runs; one of
  // 1e-6 (size sqrt(2e-6), 312 times the cells) is refused with the reason.
  for (const auto& [targets, runs] : {std::pair{"[1e-3, 1e-4]", true}, {"[1e-3, 1e-6]", false}}) {
    std::string text = kScene;
    text.replace(text.find("\"min_seconds\": 0.5"), 18,
                 std::string("\"min_seconds\": 0.5, \"targets\": ") + targets);
    const Scene scene = parse_scene(text, "made-up scene", {.tradeoff = true});
    std::vector<RunRecord> records;
    for (const StudyRun& run : expand_runs(scene)) records.push_back(made_up(run));
    const StudySummary summary = summarize_study(scene, records, nullptr);
    const TradeoffAnalysis a = analyse_tradeoff(scene, summary, records);
    std::string why_not;
    const std::optional<Scene> check = tradeoff_check_scene(scene, a, why_not);
    EXPECT_EQ(check.has_value(), runs) << targets << ": " << why_not;
    if (!runs) {
      EXPECT_NE(why_not.find("times the cells of the finest level"), std::string::npos) << why_not;
      continue;
    }
    ASSERT_EQ(check->meshes.size(), 1u);
    EXPECT_NEAR(check->meshes[0].sizes[0], std::sqrt(2e-4), 1e-9);
    EXPECT_EQ(check->meshes[0].realizations, 4);
    ASSERT_EQ(check->formulations.size(), 1u);
    EXPECT_EQ(check->formulations[0].label, "clean");
  }
}

}  // namespace
}  // namespace vorodg
