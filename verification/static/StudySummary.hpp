#pragma once
// From a study's records to its statistics: per group — (mesh, problem, material, formulation
// variant) — and level over the realizations, the sample statistics of the errors; per group the
// least-squares rates with their 95% intervals and the spread of the per-realization rates
// between consecutive levels. Typed first; summary.json is written from these (deterministic:
// no wall times), and every report and plot reads them instead of computing again.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "verification/report/RateFit.hpp"
#include "verification/report/SampleStatistics.hpp"
#include "verification/solve/RunRecord.hpp"
#include "verification/static/Scene.hpp"

namespace vorodg {

struct LevelSummary {
  int level = 0;
  double size = 0.0;
  int runs = 0, failed = 0;
  int diverged = 0;  // DG iterations that diverged: counted in the statistics, flagged apart
  // Over the realizations that ran (none if every run of the level failed):
  std::optional<double> h_avg, dofs, iterations;  // means
  std::optional<SampleStatistics> l2, energy;
};

struct RateSummary {
  RateFit fit;
  // Rates between consecutive levels of each realization: min, median, max.
  std::optional<double> pair_min, pair_median, pair_max;
};

struct GroupSummary {
  std::string key;  // "mesh | problem [| nu=...] | variant": for people
  std::string mesh, problem, formulation, label, variant;
  double nu = 0.0;
  std::optional<double> kp;
  std::vector<LevelSummary> levels;
  std::optional<RateSummary> rate_l2, rate_energy;  // with two or more levels
  std::optional<double> published_l2_rate;
};

struct StudySummary {
  std::vector<GroupSummary> groups;  // in the order of the scene's runs
  nlohmann::json published;          // the scene's reference values (null if none)
};

/// The group a run belongs to, as people read it: "mesh | problem [| nu=...] | variant".
std::string group_key(const Scene& scene, const StudyRun& run);

StudySummary summarize_study(const Scene& scene, const std::vector<RunRecord>& records,
                             const nlohmann::json& published);
/// The published values the scene's `reference` names in data/reference/published.json.
nlohmann::json published_reference(const Scene& scene);
/// summary.json: the same results give the same bytes.
nlohmann::json to_json(const Scene& scene, const StudySummary& summary);

}  // namespace vorodg
