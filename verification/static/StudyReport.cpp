#include "verification/static/StudyReport.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>

#include "core/io/AtomicFile.hpp"
#include "core/io/JsonOutput.hpp"
#include "core/util/Format.hpp"
#include "verification/harness/StudyFiles.hpp"
#include "verification/report/ConvergenceTable.hpp"
#include "verification/static/KpTrendReport.hpp"
#include "verification/static/StudySummary.hpp"

namespace vorodg {
namespace {

using nlohmann::json;

std::string csv_text(std::string s) {
  std::replace(s.begin(), s.end(), '"', '\'');
  return "\"" + s + "\"";
}

/// Seconds per stage, summed over each group's runs (wall times: never in summary.json).
void write_timings(const Scene& scene, const std::vector<RunRecord>& records,
                   const std::filesystem::path& out) {
  std::map<std::string, std::map<std::string, double>> timings;
  for (const RunRecord& r : records)
    if (r.metrics)
      for (const auto& [stage, s] : r.metrics->seconds)
        timings[group_key(scene, r.run)][stage] += s;
  write_json(out / "timings.json", json(timings));
}

ConvergenceTable convergence_table(const GroupSummary& g) {
  const ConvergenceTable::Style sci{3, true}, plain{4, false}, count{6, false};
  ConvergenceTable table;
  for (const LevelSummary& lv : g.levels) {
    table.start_row();
    table.add_value("level", lv.level, std::nullopt, count);
    std::string runs = std::to_string(lv.runs);
    if (lv.failed) runs.append(" (").append(std::to_string(lv.failed)).append(" failed)");
    if (lv.diverged) runs.append(" (").append(std::to_string(lv.diverged)).append(" diverged)");
    if (!lv.l2) {
      table.add_text("runs", runs);
      table.add_text("L2 error", "all failed");
      continue;
    }
    table.add_value("h_avg", *lv.h_avg, std::nullopt, plain);
    table.add_value("DOFs", *lv.dofs, std::nullopt, count);
    table.add_text("runs", runs);
    table.add_value("L2 error", lv.l2->mean, lv.l2->std_dev, sci);
    if (lv.energy) table.add_value("energy error", lv.energy->mean, lv.energy->std_dev, sci);
    table.add_value("iterations", *lv.iterations, std::nullopt, {3, false});
  }
  table.evaluate_convergence_rates("L2 error", "h_avg");
  if (g.levels.front().energy) table.evaluate_convergence_rates("energy error", "h_avg");
  return table;
}

std::string describe_rate(const std::optional<RateSummary>& r) {
  if (!r) return "-";
  std::string s = fmt(r->fit.rate, 3);
  if (r->fit.ci95) s += " ± " + fmt(*r->fit.ci95, 2);
  if (r->pair_min)
    s += " (per-realization pairs " + fmt(*r->pair_min, 3) + " .. " + fmt(*r->pair_max, 3) + ")";
  return s;
}

void write_rates(const GroupSummary& g, const std::string& source, std::ostringstream& md) {
  std::cout << "  least-squares rate: L2 " << describe_rate(g.rate_l2);
  md << "\nLeast-squares rates (95% interval): L2 " << describe_rate(g.rate_l2);
  if (g.rate_energy) {
    std::cout << ", energy " << describe_rate(g.rate_energy);
    md << ", energy " << describe_rate(g.rate_energy);
  }
  if (g.published_l2_rate) {
    const double ours = g.rate_l2 ? g.rate_l2->fit.rate : std::nan("");
    const double theirs = *g.published_l2_rate;
    std::cout << "; published L2 rate " << theirs;
    md << ".\nPublished L2 rate: " << theirs << " (" << source << "); ours " << fmt(ours, 3)
       << (std::abs(ours - theirs) > 0.1
               ? " — **differs** by more than 0.1 (reported as measured, not adjusted toward it)"
               : " — agrees");
  }
  std::cout << "\n";
  md << ".\n\n";
}

void write_convergence(const StudySummary& summary, const std::filesystem::path& out,
                       std::ostringstream& md) {
  std::ostringstream csv;
  for (std::size_t i = 0; i < summary.groups.size(); ++i) {
    const GroupSummary& g = summary.groups[i];
    const ConvergenceTable table = convergence_table(g);
    std::cout << "\n" << g.key << "\n";
    table.write_text(std::cout);
    md << "## " << g.key << "\n\n";
    table.write_markdown(md);
    write_rates(g, summary.published.is_object() ? summary.published.value("source", "") : "", md);
    std::ostringstream group_csv;
    table.write_csv(group_csv);
    std::istringstream lines(group_csv.str());
    std::string line;
    std::getline(lines, line);
    if (i == 0) csv << "\"group\"," << line << "\n";
    while (std::getline(lines, line)) csv << csv_text(g.key) << "," << line << "\n";
  }
  write_file_atomically(out / "convergence.csv", csv.str());
}

}  // namespace

int convergence_sections(const ReportInput& in, std::ostringstream& md) {
  write_convergence(in.summary, in.out, md);
  write_kp_trend(in.summary, md);
  return 0;
}

StudyReport write_study_report(const Scene& scene, const std::vector<RunRecord>& records,
                               const std::filesystem::path& out, const ReportSections& sections) {
  write_results_csv(out, run_record_fields(), records);
  write_timings(scene, records, out);
  const json published = published_reference(scene);
  const StudySummary summary = summarize_study(scene, records, published);
  write_summary(out, to_json(scene, summary));

  std::ostringstream md;
  md << "# " << scene.name << "\n\n"
     << scene.description << "\n\n"
     << "Study: " << scene.study << "; problems: ";
  for (const auto& p : scene.problems) md << p << " ";
  md << "; E = " << scene.E << ", plane " << plane_name(scene.plane) << "; " << records.size()
     << " runs.\n\n";
  StudyReport report;
  report.unexpected = sections({scene, summary, records, out}, md);
  if (published.is_object() && published.contains("trend"))
    md << "Published trend (" << published.value("source", "")
       << "): " << published["trend"].get<std::string>() << "\n\n";
  report.markdown = md.str();
  return report;
}

std::vector<std::string> study_pictures() {
  return {"convergence_l2.png", "convergence_energy.png", "penalty.png", "penalty_edges.png",
          "cdf_l2.png",         "tradeoff.png",           "extremes.png"};
}

void finish_report_markdown(std::string markdown, const std::filesystem::path& out,
                            const std::vector<std::string>& pictures) {
  for (const std::string& png : pictures)
    if (std::filesystem::exists(out / png)) markdown += "![" + png + "](" + png + ")\n";
  write_file_atomically(out / "report.md", markdown);
}

}  // namespace vorodg
