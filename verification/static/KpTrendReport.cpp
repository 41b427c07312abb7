#include "verification/static/KpTrendReport.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "core/util/Format.hpp"
#include "verification/report/ConvergenceTable.hpp"

namespace vorodg {
namespace {

struct Reading {
  std::string mesh, problem, label;
  std::vector<const GroupSummary*> groups;  // with a rate, by k_p, increasing
  std::vector<const GroupSummary*> all;     // every k_p, for the run counts
};

double ci(const RateFit& fit) {
  return fit.ci95.value_or(0.0);
}

/// Each rate above the previous one by more than the two intervals.
bool rises_throughout(const Reading& r) {
  for (std::size_t i = 1; i < r.groups.size(); ++i) {
    const RateFit &a = r.groups[i - 1]->rate_l2->fit, &b = r.groups[i]->rate_l2->fit;
    if (!(b.rate > a.rate + ci(a) + ci(b))) return false;
  }
  return true;
}

/// The rate at the largest k_p above the one at the smallest by more than the two intervals.
bool rises_overall(const Reading& r) {
  const RateFit &a = r.groups.front()->rate_l2->fit, &b = r.groups.back()->rate_l2->fit;
  return b.rate > a.rate + ci(a) + ci(b);
}

std::string kp_rate_text(const RateFit& fit) {
  return fmt(fit.rate, 3) + (fit.ci95 ? " ± " + fmt(*fit.ci95, 2) : "");
}

/// The readings with their groups, CG's groups by "mesh | problem", and every k_p.
struct Readings {
  std::map<std::string, Reading> by_name;
  std::map<std::string, const GroupSummary*> cg;
  std::set<double> kps;
};

Readings collect_readings(const StudySummary& summary) {
  Readings out;
  for (const GroupSummary& g : summary.groups) {
    if (!g.kp) {
      if (g.rate_l2 && g.formulation == "cg" && g.label == "cg")
        out.cg[g.mesh + " | " + g.problem] = &g;
      continue;
    }
    Reading& r = out.by_name[g.mesh + " | " + g.problem + " | " + g.label];
    r.mesh = g.mesh;
    r.problem = g.problem;
    r.label = g.label;
    r.all.push_back(&g);
    if (g.rate_l2) r.groups.push_back(&g);
    out.kps.insert(*g.kp);
  }
  std::erase_if(out.by_name, [](const auto& item) { return item.second.groups.size() < 2; });
  return out;
}

/// Which readings rise, which rise through failed or diverged runs, which reach CG's rate.
struct Verdicts {
  std::vector<std::string> rising, reaching, broken;
};

/// One reading's row: its rate at every k_p, its failures, whether it rises and reaches CG.
void add_reading(ConvergenceTable& table, Reading& r, const Readings& all, Verdicts& verdicts) {
  std::sort(r.groups.begin(), r.groups.end(), [](auto* a, auto* b) { return *a->kp < *b->kp; });
  table.start_row();
  table.add_text("mesh | problem", r.mesh + " | " + r.problem);
  table.add_text("reading", r.label);
  for (double kp : all.kps) {
    const auto at = std::find_if(r.all.begin(), r.all.end(),
                                 [&](const GroupSummary* g) { return *g->kp == kp; });
    table.add_text("k_p " + fmt(kp), at == r.all.end() ? "-"
                                     : (*at)->rate_l2  ? kp_rate_text((*at)->rate_l2->fit)
                                                       : "no rate");
  }
  int failed = 0, diverged = 0, runs = 0;
  for (const GroupSummary* g : r.all)
    for (const LevelSummary& lv : g->levels) {
      failed += lv.failed;
      diverged += lv.diverged;
      runs += lv.runs;
    }
  table.add_text(
      "failed / diverged runs",
      std::to_string(failed) + " / " + std::to_string(diverged) + " of " + std::to_string(runs));
  const bool throughout = rises_throughout(r), overall = rises_overall(r);
  table.add_text("rises", throughout ? "at every step" : overall ? "overall" : "no");
  const auto c = all.cg.find(r.mesh + " | " + r.problem);
  std::string reaches = "-";
  if (c != all.cg.end()) {
    const RateFit &last = r.groups.back()->rate_l2->fit, &ref = c->second->rate_l2->fit;
    const bool near = std::abs(last.rate - ref.rate) <= ci(last) + ci(ref);
    reaches = (near ? "yes (" : "no (") + fmt(last.rate - ref.rate, 2) + ")";
    if (overall && near && failed + diverged == 0)
      verdicts.reaching.push_back(r.label + " (" + r.mesh + ")");
  }
  table.add_text("reaches CG's rate at the largest k_p", reaches);
  if (overall)
    (failed + diverged ? verdicts.broken : verdicts.rising)
        .push_back(r.label + " (" + r.mesh + ")");
}

std::string name_list(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) out += (i ? ", " : "") + names[i];
  return out.empty() ? std::string("none") : out;
}

}  // namespace

void write_kp_trend(const StudySummary& summary, std::ostringstream& md) {
  Readings readings = collect_readings(summary);
  if (readings.by_name.empty()) return;
  ConvergenceTable table;
  Verdicts verdicts;
  for (auto& [name, r] : readings.by_name) add_reading(table, r, readings, verdicts);
  md << "## L2 rate against k_p\n\n"
     << "Least-squares L2 rate (95% interval) of each reading at each k_p. `rises`: the rate at "
        "the largest k_p exceeds the one at the smallest by more than both intervals (`overall`), "
        "or every step does (`at every step`). The last column compares the rate at the largest "
        "k_p with CG's on the same meshes (difference in brackets). Failed runs are left out of "
        "the "
        "rates; runs whose iteration diverged are in them (their last iterate), so a reading with "
        "many of either has rates that describe its breakdown, not its convergence.\n\n";
  table.write_markdown(md);
  md << "\nReadings whose rate rises with k_p, every run converged: " << name_list(verdicts.rising)
     << ". Rising only through failed or diverged runs: " << name_list(verdicts.broken)
     << ". Rising, every run converged, and reaching CG's rate at the largest k_p (the published "
        "figure's picture): "
     << name_list(verdicts.reaching) << ".\n\n";
}

}  // namespace vorodg
