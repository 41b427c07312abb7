#include "verification/study/TradeoffReport.hpp"

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <map>

#include "core/util/Format.hpp"
#include "verification/cli/JsonOutput.hpp"

namespace vorodg {
namespace {

using nlohmann::json;

struct CostPoint {
  std::string variant;
  int level;
  double h, error, seconds;
};

std::string scientific(double x) {
  std::ostringstream os;
  os << std::scientific << std::setprecision(3) << x;
  return os.str();
}

/// Per (variant, level): mean h_avg and L2 error, median total seconds.
std::vector<CostPoint> cost_points(const std::vector<RunRecord>& records,
                                   std::vector<std::string>& variants) {
  std::map<std::pair<std::string, int>, std::vector<const RunMetrics*>> groups;
  for (const RunRecord& r : records) {
    if (!r.ok()) continue;
    if (std::find(variants.begin(), variants.end(), r.run.variant) == variants.end())
      variants.push_back(r.run.variant);
    groups[{r.run.variant, r.run.level}].push_back(&*r.metrics);
  }
  std::vector<CostPoint> points;
  for (const auto& [key, runs] : groups) {
    std::vector<double> t;
    double mean_e = 0, mean_h = 0;
    for (const RunMetrics* m : runs) {
      t.push_back(m->total_seconds());
      mean_e += m->l2_error / runs.size(), mean_h += m->h_avg / runs.size();
    }
    std::sort(t.begin(), t.end());
    points.push_back({key.first, key.second, mean_h, mean_e, t[t.size() / 2]});
  }
  std::sort(points.begin(), points.end(),
            [](const CostPoint& a, const CostPoint& b) { return a.seconds < b.seconds; });
  return points;
}

void write_knob_table(const std::vector<CostPoint>& points,
                      const std::vector<std::string>& variants, std::ostringstream& md) {
  int levels = 0;
  for (const CostPoint& p : points) levels = std::max(levels, p.level + 1);
  md << "\nWhat each knob adds at fixed h, against `" << variants.front()
     << "` (ratios of mean L2 error and of median seconds, per level):\n\n| configuration |";
  for (int l = 0; l < levels; ++l) md << " level " << l << " error | level " << l << " time |";
  md << "\n|---|";
  for (int l = 0; l < levels; ++l) md << "---|---|";
  md << "\n";
  auto find = [&](const std::string& v, int l) -> const CostPoint* {
    for (const CostPoint& p : points)
      if (p.variant == v && p.level == l) return &p;
    return nullptr;
  };
  for (const std::string& v : variants) {
    md << "| " << v << " |";
    for (int l = 0; l < levels; ++l) {
      const CostPoint *p = find(v, l), *base = find(variants.front(), l);
      if (p && base)
        md << " " << fmt(p->error / base->error, 3) << " | " << fmt(p->seconds / base->seconds, 3)
           << " |";
      else
        md << " - | - |";
    }
    md << "\n";
  }
  md << "\n";
}

}  // namespace

void write_tradeoff(const std::vector<RunRecord>& records, const std::filesystem::path& out,
                    std::ostringstream& md) {
  std::vector<std::string> variants;
  const std::vector<CostPoint> points = cost_points(records, variants);
  if (points.empty()) return;
  std::vector<const CostPoint*> front;  // by increasing time, strictly decreasing error
  for (const CostPoint& p : points)
    if (front.empty() || p.error < front.back()->error) front.push_back(&p);
  json data = {{"points", json::array()}, {"pareto", json::array()}};
  for (const CostPoint& p : points)
    data["points"].push_back({{"variant", p.variant},
                              {"level", p.level},
                              {"h_avg", p.h},
                              {"l2_error", p.error},
                              {"seconds", p.seconds}});
  md << "## Error against wall time\n\nPareto front (median total seconds per run over the "
        "realizations; no other configuration is both cheaper and more accurate). For a target "
        "error e, the cheapest configuration is the first row whose error is at most e:\n\n"
        "| L2 error | seconds | configuration | level | h_avg |\n|---|---|---|---|---|\n";
  std::cout << "\nPareto front (error against median wall time per run):\n";
  for (const CostPoint* p : front) {
    data["pareto"].push_back({{"variant", p->variant},
                              {"level", p->level},
                              {"l2_error", p->error},
                              {"seconds", p->seconds}});
    md << "| " << scientific(p->error) << " | " << fmt(p->seconds, 3) << " | " << p->variant
       << " | " << p->level << " | " << fmt(p->h, 4) << " |\n";
    std::cout << "  " << scientific(p->error) << "  " << std::setw(9) << fmt(p->seconds, 3)
              << " s  " << p->variant << ", level " << p->level << "\n";
  }
  write_knob_table(points, variants, md);
  write_json(out / "tradeoff.json", data);
}

}  // namespace vorodg
