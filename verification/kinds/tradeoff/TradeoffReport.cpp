#include "verification/kinds/tradeoff/TradeoffReport.hpp"

#include <iomanip>
#include <iostream>

#include "core/io/JsonOutput.hpp"
#include "core/util/Format.hpp"
#include "verification/kinds/tradeoff/TradeoffVerification.hpp"
#include "verification/report/ConvergenceTable.hpp"

namespace vorodg {
namespace {

using nlohmann::json;

std::string scientific(double x) {
  std::ostringstream os;
  os << std::scientific << std::setprecision(3) << x;
  return os.str();
}

std::string tradeoff_rate_text(const std::optional<RateSummary>& r) {
  return r ? fmt(r->fit.rate, 3) : "-";
}

std::string time_range(const TradeoffLevel& lv) {
  return fmt(lv.seconds_min, 3) + "-" + fmt(lv.seconds_max, 3);
}

/// One row of texts, each cell formatted here (the report's numbers carry their own digits).
void add_row(ConvergenceTable& t, const std::vector<std::pair<std::string, std::string>>& cells) {
  t.start_row();
  for (const auto& [column, text] : cells) t.add_text(column, text);
}

/// The header of a table without rows.
void add_header_only(ConvergenceTable& t, const std::vector<std::string>& columns) {
  for (const std::string& c : columns) t.declare_column(c);
}

std::string markdown(const ConvergenceTable& t) {
  std::ostringstream md;
  t.write_markdown(md);
  return md.str();
}

/// Which configurations converge, and why the others may not stand on the front.
void write_admission(const TradeoffAnalysis& a, const TradeoffSettings& s, std::ostringstream& md) {
  md << "## Which configurations converge\n\nA configuration stands on the front only if its "
        "least-squares L2 and energy rates are within "
     << fmt(100 * s.rate_tolerance) << "% of " << fmt(kExpectedL2Rate) << " and "
     << fmt(kExpectedEnergyRate)
     << ", every realization's rate between consecutive levels is positive, its mean L2 error "
        "falls at every level, no run failed, and at least two levels take "
     << fmt(s.min_seconds) << " s or more (the error-cost line).\n\n";
  ConvergenceTable t;
  for (const TradeoffConfig& c : a.configs) {
    const auto& pair = c.group->rate_l2;
    add_row(t, {{"configuration", c.variant},
                {"L2 rate", tradeoff_rate_text(c.group->rate_l2)},
                {"energy rate", tradeoff_rate_text(c.group->rate_energy)},
                {"lowest L2 pair rate", pair && pair->pair_min ? fmt(*pair->pair_min, 3) : "-"},
                {"verdict", c.admitted() ? "admitted" : "**excluded**"}});
  }
  md << markdown(t);
  bool any = false;
  for (const TradeoffConfig& c : a.configs) {
    if (c.admitted()) continue;
    if (!any) md << "\nExcluded, with every reason:\n\n";
    any = true;
    md << "- **" << c.variant << "**: ";
    for (std::size_t i = 0; i < c.exclusions.size(); ++i) md << (i ? "; " : "") << c.exclusions[i];
    md << ".\n";
  }
  md << "\n";
}

/// The error-cost slope and the seconds per DOF of every configuration with a cost line.
void write_costs(const TradeoffAnalysis& a, const TradeoffSettings& s, std::ostringstream& md) {
  md << "## What accuracy costs\n\nOnly levels whose median run takes at least "
     << fmt(s.min_seconds)
     << " s are timed. Seconds are the median of the realizations, with their range; the "
        "slope s is that of L2 error ~ time^-s over the timed levels: the larger, the faster "
        "the error falls as the problem grows.\n\n";
  ConvergenceTable t;
  for (const TradeoffConfig& c : a.configs) {
    if (!c.cost_fit) continue;
    int timed = 0;
    const TradeoffLevel* finest = nullptr;
    for (const TradeoffLevel& lv : c.levels)
      if (lv.timed) ++timed, finest = &lv;
    add_row(t,
            {{"configuration", c.variant + (c.admitted() ? "" : " (excluded)")},
             {"timed levels", std::to_string(timed)},
             {"error-cost slope s", fmt(c.slope(), 3)},
             {"microseconds per DOF", fmt(1e6 * *c.seconds_per_dof, 3)},
             {"finest: median s", fmt(finest->seconds, 3)},
             {"range s", time_range(*finest)},
             {"spread",
              fmt(100 * (finest->seconds_max - finest->seconds_min) / finest->seconds, 2) + "%"}});
  }
  if (t.rows() == 0)
    add_header_only(t, {"configuration", "timed levels", "error-cost slope s",
                        "microseconds per DOF", "finest: median s", "range s", "spread"});
  md << markdown(t) << "\n";
}

void write_front(const TradeoffAnalysis& a, std::ostringstream& md) {
  md << "## Pareto front\n\nAdmitted configurations at their timed levels; no other point is "
        "both cheaper and more accurate.\n\n";
  std::cout << "\nPareto front (admitted configurations, timed levels):\n";
  ConvergenceTable t;
  for (const TradeoffPoint& p : a.front) {
    const TradeoffLevel& lv = *p.level;
    add_row(t, {{"L2 error", scientific(lv.l2_error)},
                {"median s", fmt(lv.seconds, 3)},
                {"range s", time_range(lv)},
                {"configuration", p.config->variant},
                {"level", std::to_string(lv.level)},
                {"h_avg", fmt(lv.h_avg, 4)},
                {"DOFs", fmt(lv.dofs, 6)}});
    std::cout << "  " << scientific(lv.l2_error) << "  " << std::setw(9) << fmt(lv.seconds, 3)
              << " s  " << p.config->variant << ", level " << lv.level << "\n";
  }
  if (a.front.empty())
    add_header_only(t,
                    {"L2 error", "median s", "range s", "configuration", "level", "h_avg", "DOFs"});
  md << markdown(t);
  if (a.front.empty()) md << "(empty: no admitted configuration has a timed level)\n";
  md << "\n";
}

void write_recommendation(const TradeoffAnalysis& a, const TradeoffSettings& s,
                          std::ostringstream& md) {
  md << "## Recommendation\n\n";
  for (const TradeoffTarget& t : a.targets) {
    md << "- To reach an L2 error of " << scientific(t.error) << " on this problem, ";
    if (!t.config) {
      md << "no admitted configuration has an error-cost line.\n";
      continue;
    }
    md << "use **" << t.config->variant << "** (predicted " << fmt(t.seconds, 3)
       << " s per run from its error-cost line, mesh size " << fmt(t.size, 4) << ")";
    if (t.seconds < s.min_seconds)
      md << "; a run this short is under the " << fmt(s.min_seconds)
         << " s that can be timed, so the time is the line's extrapolation only";
    else if (t.extrapolated)
      md << "; extrapolated beyond its timed levels";
    md << ".\n";
  }
  md << "\n";
}

void write_check(const std::optional<TradeoffCheck>& check, const std::string& why_not,
                 std::ostringstream& md) {
  md << "## Check of the recommendation\n\n";
  if (!check) {
    md << "Not run: " << why_not << ".\n\n";
    return;
  }
  const TradeoffTarget& t = check->target;
  md << "The recommendation for " << scientific(t.error) << " (" << t.config->variant
     << ") ran again at the predicted mesh size " << fmt(t.size, 4) << " on " << check->runs
     << " fresh meshes (" << check->failed << " failed), in `" << kTradeoffCheckFolder << "/`.\n\n";
  if (!check->seconds) {
    md << "Every check run failed.\n\n";
    return;
  }
  ConvergenceTable table;
  add_row(table, {{"", "seconds per run (median)"},
                  {"predicted", fmt(t.seconds, 3)},
                  {"measured", fmt(*check->seconds, 3) + " (range " + fmt(*check->seconds_min, 3) +
                                   "-" + fmt(*check->seconds_max, 3) + ")"}});
  add_row(table, {{"", "L2 error (mean)"},
                  {"predicted", scientific(t.error)},
                  {"measured", scientific(*check->l2_error)}});
  md << markdown(table)
     << "\nMeasured time / predicted - 1: " << fmt(100 * *check->time_deviation(), 3) << "%.\n\n";
}

/// Per knob, its error and time at fixed level against the first configuration (times only
/// where both levels are timed: shorter runs say nothing reliable about their ratio).
void write_knob_table(const TradeoffAnalysis& a, std::ostringstream& md) {
  int levels = 0;
  for (const TradeoffConfig& c : a.configs)
    for (const TradeoffLevel& lv : c.levels) levels = std::max(levels, lv.level + 1);
  const TradeoffConfig& base = a.configs.front();
  md << "What each knob adds at fixed level, against `" << base.variant
     << "` (ratios of mean L2 error and of median seconds; '-' where a level is missing or too "
        "short to time):\n\n";
  auto find = [](const TradeoffConfig& c, int l) -> const TradeoffLevel* {
    for (const TradeoffLevel& lv : c.levels)
      if (lv.level == l) return &lv;
    return nullptr;
  };
  ConvergenceTable t;
  for (const TradeoffConfig& c : a.configs) {
    std::vector<std::pair<std::string, std::string>> cells = {{"configuration", c.variant}};
    for (int l = 0; l < levels; ++l) {
      const TradeoffLevel *p = find(c, l), *b = find(base, l);
      const std::string level = "level " + std::to_string(l);
      cells.push_back({level + " error", p && b ? fmt(p->l2_error / b->l2_error, 3) : "-"});
      cells.push_back({level + " time",
                       p && b && p->timed && b->timed ? fmt(p->seconds / b->seconds, 3) : "-"});
    }
    add_row(t, cells);
  }
  md << markdown(t) << "\n";
}

json tradeoff_level_json(const TradeoffConfig& c, const TradeoffLevel& lv) {
  return {{"variant", c.variant},
          {"level", lv.level},
          {"size", lv.size},
          {"h_avg", lv.h_avg},
          {"dofs", lv.dofs},
          {"l2_error", lv.l2_error},
          {"seconds", lv.seconds},
          {"seconds_min", lv.seconds_min},
          {"seconds_max", lv.seconds_max},
          {"runs", lv.runs},
          {"timed", lv.timed},
          {"admitted", c.admitted()}};
}

json tradeoff_json(const TradeoffAnalysis& a, const std::optional<TradeoffCheck>& check,
                   const std::string& why_not) {
  json data = {{"points", json::array()},
               {"configs", json::array()},
               {"pareto", json::array()},
               {"targets", json::array()}};
  for (const TradeoffConfig& c : a.configs) {
    json j = {{"variant", c.variant}, {"admitted", c.admitted()}, {"exclusions", c.exclusions}};
    if (c.cost_fit)
      j["cost_line"] = {{"slope", c.slope()},
                        {"intercept", c.cost_fit->intercept},
                        {"seconds_per_dof", *c.seconds_per_dof}};
    data["configs"].push_back(j);
    for (const TradeoffLevel& lv : c.levels) data["points"].push_back(tradeoff_level_json(c, lv));
  }
  for (const TradeoffPoint& p : a.front)
    data["pareto"].push_back(tradeoff_level_json(*p.config, *p.level));
  for (const TradeoffTarget& t : a.targets) {
    json j = {{"error", t.error}};
    if (t.config)
      j.update({{"variant", t.config->variant},
                {"seconds", t.seconds},
                {"size", t.size},
                {"extrapolated", t.extrapolated}});
    data["targets"].push_back(j);
  }
  if (check && check->seconds)
    data["check"] = {{"variant", check->target.config->variant},
                     {"target", check->target.error},
                     {"predicted_seconds", check->target.seconds},
                     {"size", check->target.size},
                     {"seconds", *check->seconds},
                     {"seconds_min", *check->seconds_min},
                     {"seconds_max", *check->seconds_max},
                     {"l2_error", *check->l2_error},
                     {"runs", check->runs},
                     {"failed", check->failed}};
  else
    data["check"] = {{"not_run", check ? "every check run failed" : why_not}};
  return data;
}

}  // namespace

void write_tradeoff(const Scene& scene, const StudySummary& summary,
                    const std::vector<RunRecord>& records, const std::filesystem::path& out,
                    std::ostringstream& md) {
  const TradeoffAnalysis a = analyse_tradeoff(scene, summary, records);
  if (a.configs.empty()) return;
  std::string why_not;
  std::optional<TradeoffCheck> check;
  if (const auto check_scene = tradeoff_check_scene(scene, a, why_not)) {
    check = read_tradeoff_check(*check_scene, a.targets.back(), out);
    if (!check)
      why_not = "its runs are not in " + std::string(kTradeoffCheckFolder) +
                "/ (a study split over MPI ranks or shards runs no check)";
  }
  write_admission(a, scene.tradeoff, md);
  write_costs(a, scene.tradeoff, md);
  write_front(a, md);
  write_recommendation(a, scene.tradeoff, md);
  write_check(check, why_not, md);
  write_knob_table(a, md);
  write_json(out / "tradeoff.json", tradeoff_json(a, check, why_not));
}

}  // namespace vorodg
