#include "verification/kinds/tradeoff/TradeoffAnalysis.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/util/Format.hpp"

namespace vorodg {
namespace {

/// Every reason a rate says the configuration does not converge as expected.
void check_rate(const std::optional<RateSummary>& rate, const std::string& norm, double expected,
                double tolerance, std::vector<std::string>& reasons) {
  if (!rate) {
    reasons.push_back("no " + norm + " rate (fewer than two levels with results)");
    return;
  }
  const double r = rate->fit.rate;
  if (!(std::abs(r - expected) <= tolerance * expected))
    reasons.push_back(norm + " rate " + fmt(r, 3) + " outside " + fmt(expected) + " +- " +
                      fmt(tolerance * expected, 3));
  if (rate->pair_min && !(*rate->pair_min > 0))
    reasons.push_back("a realization's " + norm + " rate between two levels is " +
                      fmt(*rate->pair_min, 3) + " (<= 0)");
}

/// The mean error must fall from every level to the next.
void check_monotone(const GroupSummary& g, std::vector<std::string>& reasons) {
  for (std::size_t l = 1; l < g.levels.size(); ++l) {
    const auto& a = g.levels[l - 1].l2;
    const auto& b = g.levels[l].l2;
    if (a && b && !(b->mean < a->mean))
      reasons.push_back("mean L2 error rises from level " + std::to_string(l - 1) + " (" +
                        fmt(a->mean, 3) + ") to level " + std::to_string(l) + " (" +
                        fmt(b->mean, 3) + ")");
  }
}

std::vector<std::string> exclusions(const GroupSummary& g, const Scene& scene) {
  std::vector<std::string> reasons;
  int failed = 0, diverged = 0, runs = 0, levels = 0;
  for (const LevelSummary& lv : g.levels) {
    failed += lv.failed, diverged += lv.diverged, runs += lv.runs;
    levels += lv.l2.has_value();
  }
  if (failed > 0)
    reasons.push_back(std::to_string(failed) + " of " + std::to_string(runs) + " runs failed");
  if (diverged > 0)
    reasons.push_back(std::to_string(diverged) + " of " + std::to_string(runs) +
                      " runs' iterations diverged");
  if (levels < 3)
    reasons.push_back("only " + std::to_string(levels) +
                      " levels with results: a rate needs three to be judged");
  const double tolerance = scene.tradeoff.rate_tolerance;
  check_rate(g.rate_l2, "L2", kExpectedL2Rate, tolerance, reasons);
  if (scene.energy_error)
    check_rate(g.rate_energy, "energy", kExpectedEnergyRate, tolerance, reasons);
  check_monotone(g, reasons);
  return reasons;
}

/// Per level of the group: the summary's means and the runs' median and range of seconds.
std::vector<TradeoffLevel> tradeoff_levels_of(const GroupSummary& g,
                                              const std::vector<const RunRecord*>& runs,
                                              double min_seconds) {
  std::vector<TradeoffLevel> out;
  for (const LevelSummary& lv : g.levels) {
    if (!lv.l2) continue;
    std::vector<double> t;
    for (const RunRecord* r : runs)
      if (r->run.level == lv.level && r->ok()) t.push_back(r->metrics->total_seconds());
    const SampleStatistics time = sample_statistics(t);
    out.push_back({lv.level, lv.size, *lv.h_avg, *lv.dofs, lv.l2->mean, time.median, time.min,
                   time.max, static_cast<int>(t.size()), time.median >= min_seconds});
  }
  return out;
}

/// The cost line over the timed levels and the size line over every level (two points each at
/// least); the seconds per DOF of the finest timed level.
void fit_lines(TradeoffConfig& c) {
  std::vector<double> t, et, size, es;
  for (const TradeoffLevel& lv : c.levels) {
    size.push_back(lv.size), es.push_back(lv.l2_error);
    if (lv.timed) {
      t.push_back(lv.seconds), et.push_back(lv.l2_error);
      c.seconds_per_dof = lv.seconds / lv.dofs;
    }
  }
  if (size.size() >= 2) c.size_fit = fit_rate(size, es);
  if (t.size() >= 2) c.cost_fit = fit_rate(t, et);
}

std::vector<TradeoffPoint> pareto_front(const std::vector<TradeoffConfig>& configs) {
  std::vector<TradeoffPoint> points;
  for (const TradeoffConfig& c : configs)
    if (c.admitted())
      for (const TradeoffLevel& lv : c.levels)
        if (lv.timed) points.push_back({&c, &lv});
  std::sort(points.begin(), points.end(), [](const TradeoffPoint& a, const TradeoffPoint& b) {
    return a.level->seconds < b.level->seconds;
  });
  std::vector<TradeoffPoint> front;
  for (const TradeoffPoint& p : points)
    if (front.empty() || p.level->l2_error < front.back().level->l2_error) front.push_back(p);
  return front;
}

/// Three decades down to the power of ten at or below the best error of a finest timed level.
std::vector<double> default_targets(const std::vector<TradeoffConfig>& configs) {
  double best = INFINITY;
  for (const TradeoffConfig& c : configs)
    if (c.admitted()) best = std::min(best, c.levels.back().l2_error);
  if (!std::isfinite(best)) return {};
  const double lowest = std::pow(10.0, std::floor(std::log10(best)));
  return {100 * lowest, 10 * lowest, lowest};
}

TradeoffTarget recommend(const std::vector<TradeoffConfig>& configs, double e) {
  TradeoffTarget best{e, nullptr, INFINITY, 0.0, false};
  for (const TradeoffConfig& c : configs) {
    if (!c.admitted()) continue;
    const double t = c.predicted_seconds(e);
    if (!(t < best.seconds)) continue;
    double lo = INFINITY, hi = 0.0;
    for (const TradeoffLevel& lv : c.levels)
      if (lv.timed) lo = std::min(lo, lv.l2_error), hi = std::max(hi, lv.l2_error);
    best = {e, &c, t, c.predicted_size(e), e < lo || e > hi};
  }
  return best;
}

}  // namespace

double TradeoffConfig::predicted_seconds(double e) const {
  return std::exp((std::log(e) - cost_fit->intercept) / cost_fit->rate);
}

double TradeoffConfig::predicted_size(double e) const {
  return std::exp((std::log(e) - size_fit->intercept) / size_fit->rate);
}

TradeoffAnalysis analyse_tradeoff(const Scene& scene, const StudySummary& summary,
                                  const std::vector<RunRecord>& records) {
  std::map<std::string, std::vector<const RunRecord*>> by_group;
  for (const RunRecord& r : records) by_group[group_key(scene, r.run)].push_back(&r);
  TradeoffAnalysis a;
  for (const GroupSummary& g : summary.groups) {
    TradeoffConfig c;
    c.variant = g.variant;
    c.group = &g;
    c.levels = tradeoff_levels_of(g, by_group[g.key], scene.tradeoff.min_seconds);
    c.exclusions = exclusions(g, scene);
    fit_lines(c);
    if (!c.cost_fit) {
      int timed = 0;
      for (const TradeoffLevel& lv : c.levels) timed += lv.timed;
      c.exclusions.push_back(std::to_string(timed) +
                             " of its levels take >= " + fmt(scene.tradeoff.min_seconds) +
                             " s, fewer than the two an error-cost line needs");
    } else if (!(c.slope() > 0)) {
      c.exclusions.push_back("the error does not fall with time (error-cost slope " +
                             fmt(c.slope(), 3) + ")");
    }
    a.configs.push_back(std::move(c));
  }
  a.front = pareto_front(a.configs);
  const std::vector<double> targets =
      scene.tradeoff.targets.empty() ? default_targets(a.configs) : scene.tradeoff.targets;
  for (double e : targets) a.targets.push_back(recommend(a.configs, e));
  return a;
}

}  // namespace vorodg
