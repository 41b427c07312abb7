// The study summary (verification/static/StudySummary): statistics over realizations, rates
// from the one fit, spreads only where there are two or more realizations, and groups kept
// apart by their typed fields.
#include "verification/static/StudySummary.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace vorodg {
namespace {

Scene two_level_scene(int realizations) {
  Scene s;
  s.name = "hand";
  s.nu = {0.3};
  SceneMesh m;
  m.label = "rcp";
  m.sizes = {0.2, 0.1};
  m.realizations = realizations;
  s.meshes = {m};
  SceneFormulation cg;
  cg.label = "cg";
  s.formulations = {cg};
  return s;
}

RunRecord record(int level, int realization, double h, double e, std::optional<double> kp = {}) {
  RunRecord r;
  r.run.mesh_label = "rcp";
  r.run.level = level;
  r.run.realization = realization;
  r.run.size = level == 0 ? 0.2 : 0.1;
  r.run.problem = "beam";
  r.run.nu = 0.3;
  r.run.formulation_name = kp ? "dg-al" : "cg";
  r.run.formulation_label = r.run.formulation_name;
  r.run.kp = kp;
  r.run.variant = kp ? "dg-al kp=1000" : "cg";
  RunMetrics m;
  m.h_avg = h;
  m.l2_error = e;
  m.energy_error = std::sqrt(e);
  m.dofs = 100 * (level + 1);
  r.metrics = m;
  return r;
}

TEST(StudySummary, MeansSpreadsAndTheRateOfTheOneFit) {
  const Scene scene = two_level_scene(2);
  const std::vector<RunRecord> records = {record(0, 0, 0.2, 4e-2), record(0, 1, 0.21, 5e-2),
                                          record(1, 0, 0.1, 1e-2), record(1, 1, 0.11, 1.1e-2)};
  const StudySummary summary = summarize_study(scene, records, nullptr);
  ASSERT_EQ(summary.groups.size(), 1u);
  const GroupSummary& g = summary.groups[0];
  EXPECT_EQ(g.key, "rcp | beam | cg");
  ASSERT_EQ(g.levels.size(), 2u);
  EXPECT_NEAR(g.levels[0].l2->mean, 4.5e-2, 1e-16);
  EXPECT_NEAR(*g.levels[0].l2->std_dev, std::sqrt(0.5) * 1e-2, 1e-16);
  EXPECT_NEAR(*g.levels[1].h_avg, 0.105, 1e-16);
  const RateFit direct = fit_rate({0.2, 0.21, 0.1, 0.11}, {4e-2, 5e-2, 1e-2, 1.1e-2});
  ASSERT_TRUE(g.rate_l2.has_value());
  EXPECT_EQ(g.rate_l2->fit.rate, direct.rate);
  EXPECT_EQ(*g.rate_l2->fit.ci95, *direct.ci95);
  // Per realization: log(4)/log(2) = 2 and log(50/11)/log(21/11).
  EXPECT_NEAR(*g.rate_l2->pair_min, 2.0, 1e-14);
  EXPECT_NEAR(*g.rate_l2->pair_max, std::log(50.0 / 11) / std::log(21.0 / 11), 1e-14);
}

TEST(StudySummary, OneRealizationHasNoSpread) {
  const Scene scene = two_level_scene(1);
  const StudySummary summary =
      summarize_study(scene, {record(0, 0, 0.2, 4e-2), record(1, 0, 0.1, 1e-2)}, nullptr);
  EXPECT_FALSE(summary.groups[0].levels[0].l2->std_dev.has_value());
  const nlohmann::json j = to_json(scene, summary);
  EXPECT_FALSE(j["groups"][0]["levels"][0]["l2"].contains("std"));
  EXPECT_TRUE(j["groups"][0]["rate_l2"]["ci95"].is_null());  // two points: no interval
  EXPECT_NEAR(j["groups"][0]["rate_l2"]["value"].get<double>(), 2.0, 1e-14);
  EXPECT_NEAR(j["groups"][0]["rate_l2"]["intercept"].get<double>(), std::log(1.0), 1e-14);
}

TEST(StudySummary, FailedRunsAreCountedNotAveraged) {
  const Scene scene = two_level_scene(2);
  RunRecord failed = record(1, 1, 0.1, 0.0);
  failed.metrics.reset();
  failed.error = "not positive definite";
  const StudySummary summary = summarize_study(
      scene, {record(0, 0, 0.2, 4e-2), record(0, 1, 0.2, 4e-2), record(1, 0, 0.1, 1e-2), failed},
      nullptr);
  const LevelSummary& fine = summary.groups[0].levels[1];
  EXPECT_EQ(fine.runs, 2);
  EXPECT_EQ(fine.failed, 1);
  EXPECT_EQ(fine.l2->values.size(), 1u);
}

TEST(StudySummary, DgGroupsCarryTheirPenaltyAsANumber) {
  const Scene scene = two_level_scene(1);
  const StudySummary summary = summarize_study(
      scene, {record(0, 0, 0.2, 4e-2, 1e3), record(1, 0, 0.1, 1e-2, 1e3), record(0, 0, 0.2, 4e-2)},
      nullptr);
  ASSERT_EQ(summary.groups.size(), 2u);
  EXPECT_EQ(summary.groups[0].kp, 1e3);
  EXPECT_EQ(summary.groups[0].label, "dg-al");
  EXPECT_FALSE(summary.groups[1].kp.has_value());
  EXPECT_FALSE(summary.groups[1].rate_l2.has_value());  // one level: no rate
}

}  // namespace
}  // namespace vorodg
