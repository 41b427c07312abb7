#pragma once
// What a trade-off study concludes, kept apart from how it is written (TradeoffReport) so that
// it can be tested on made-up runs. Three questions, in order:
//   1. Does a configuration converge? Its least-squares L2 and energy rates must lie within the
//      tolerance of the expected ones (2 and 1), every realization's rate between consecutive
//      levels must be positive, the mean errors must fall at every level, and no run may have
//      failed. A configuration that fails any of these is excluded, with every reason, and never
//      stands on the front: a mean error that dips through a sign change of the underlying error
//      looks accurate at one level only.
//   2. What does accuracy cost? Only levels whose median run takes at least min_seconds are
//      timed (shorter runs are as noisy as they are long); each admitted configuration gets the
//      line log e = a - s log t over its timed levels, the error-cost slope s that says which
//      knob wins as the problem grows, and its seconds per DOF.
//   3. What should a user run? For each target error, the admitted configuration whose line
//      predicts the least time, with that time and the mesh size its error-size line predicts.
#include <optional>
#include <string>
#include <vector>

#include "verification/report/RateFit.hpp"
#include "verification/solve/RunRecord.hpp"
#include "verification/static/StudySummary.hpp"
#include "verification/static/TradeoffSettings.hpp"

namespace vorodg {

/// Expected rates of the first-order elements vorodg has.
inline constexpr double kExpectedL2Rate = 2.0;
inline constexpr double kExpectedEnergyRate = 1.0;

struct TradeoffLevel {
  int level = 0;
  double size = 0.0;                                           // the scene's d or h of the level
  double h_avg = 0.0, dofs = 0.0, l2_error = 0.0;              // means over the realizations
  double seconds = 0.0, seconds_min = 0.0, seconds_max = 0.0;  // median and range of the runs
  int runs = 0;
  bool timed = false;  // median at least min_seconds
};

struct TradeoffConfig {
  std::string variant;  // for people
  const GroupSummary* group = nullptr;
  std::vector<TradeoffLevel> levels;      // levels with at least one finished run, coarse to fine
  std::vector<std::string> exclusions;    // why it may not stand on the front (empty: admitted)
  std::optional<RateFit> cost_fit;        // log e against log t over the timed levels
  std::optional<RateFit> size_fit;        // log e against log size over every level
  std::optional<double> seconds_per_dof;  // finest timed level: median seconds / mean DOFs

  bool admitted() const { return exclusions.empty(); }
  /// s of e ~ t^-s (the negated slope of cost_fit).
  double slope() const { return -cost_fit->rate; }
  /// The time and the mesh size at which the fitted lines reach error e.
  double predicted_seconds(double e) const;
  double predicted_size(double e) const;
};

struct TradeoffPoint {
  const TradeoffConfig* config = nullptr;
  const TradeoffLevel* level = nullptr;
};

struct TradeoffTarget {
  double error = 0.0;
  const TradeoffConfig* config = nullptr;  // none: no admitted configuration has a cost line
  double seconds = 0.0, size = 0.0;        // predicted
  bool extrapolated = false;  // e outside the errors of the configuration's timed levels
};

struct TradeoffAnalysis {
  std::vector<TradeoffConfig> configs;  // in the scene's order
  std::vector<TradeoffPoint> front;     // admitted, timed; cheapest first, error falling
  std::vector<TradeoffTarget> targets;  // largest error first
};

/// The analysis of a trade-off study's records; `summary` must outlive the result.
TradeoffAnalysis analyse_tradeoff(const Scene& scene, const StudySummary& summary,
                                  const std::vector<RunRecord>& records);

}  // namespace vorodg
