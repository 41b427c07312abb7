#include "verification/kinds/dynamics/FragmentLevels.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "verification/report/ConvergenceTable.hpp"

namespace fs = std::filesystem;

namespace vorodg {
namespace {

/// A level is distinguishable from the next coarser one below this p-value.
constexpr double kSignificance = 0.05;

/// Each fragment's mass over the run's total, from the `mass` column of fragments/<run>.csv.
std::vector<double> mass_fractions(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  if (!in || !std::getline(in, line) || line.rfind("fragment,mass,", 0) != 0)
    throw InputError(file.string() + ": expected a fragment table with header fragment,mass,...");
  std::vector<double> masses;
  for (int row = 2; std::getline(in, line); ++row) {
    const std::size_t a = line.find(','), b = line.find(',', a + 1);
    try {
      masses.push_back(std::stod(line.substr(a + 1, b - a - 1)));
    } catch (const std::exception&) {
      throw InputError(file.string() + " line " + std::to_string(row) +
                       ": expected a mass in the second column, found '" + line + "'");
    }
  }
  double total = 0.0;
  for (double m : masses) total += m;
  if (masses.empty() || !(total > 0.0))
    throw InputError(file.string() + ": expected fragments with positive mass");
  for (double& m : masses) m /= total;
  return masses;
}

std::string spread(const SampleStatistics& s, int precision) {
  return fmt(s.mean, precision) + (s.std_dev ? " ± " + fmt(*s.std_dev, 2) : "");
}

}  // namespace

std::vector<FragmentLevel> fragment_levels(const std::vector<DynamicsRecord>& records,
                                           const fs::path& out) {
  std::map<std::pair<std::string, int>, std::vector<const DynamicsRecord*>> groups;
  for (const DynamicsRecord& r : records)
    if (r.complete) groups[{r.run.label, r.run.level}].push_back(&r);
  std::vector<FragmentLevel> levels;
  for (const auto& [key, runs] : groups) {
    FragmentLevel l;
    l.mesh = key.first, l.level = key.second;
    std::vector<double> count, largest, seconds;
    for (const DynamicsRecord* r : runs) {
      l.h_avg += r->h_avg / static_cast<double>(runs.size());
      count.push_back(r->measures.fragments);
      largest.push_back(r->measures.max_fragment_mass_fraction);
      seconds.push_back(r->seconds);
      const std::vector<double> f = mass_fractions(out / "fragments" / (r->run.id() + ".csv"));
      l.mass_fractions.insert(l.mass_fractions.end(), f.begin(), f.end());
    }
    l.fragments = sample_statistics(count), l.largest = sample_statistics(largest);
    std::sort(seconds.begin(), seconds.end());
    const std::size_t n = seconds.size();
    l.median_seconds = n % 2 ? seconds[n / 2] : 0.5 * (seconds[n / 2 - 1] + seconds[n / 2]);
    levels.push_back(std::move(l));
  }
  std::stable_sort(
      levels.begin(), levels.end(),
      [](const FragmentLevel& a, const FragmentLevel& b) { return a.h_avg > b.h_avg; });
  for (std::size_t i = 1; i < levels.size(); ++i)
    levels[i].against_coarser =
        ks_two_sample(levels[i - 1].mass_fractions, levels[i].mass_fractions);
  return levels;
}

namespace {

/// One table for levels.csv and the report: the report shows means with their spread and the
/// KS distance with its p-value; the CSV has each number in a column of its own.
ConvergenceTable fragment_levels_table(const std::vector<FragmentLevel>& levels) {
  ColumnStyle plain, csv_only, text_only;
  plain.csv_quoted = false;
  csv_only.in_text = false, csv_only.csv_precision = 10;
  text_only.in_csv = false;
  const ColumnStyle count = integer_style();
  ColumnStyle h{4}, seconds{3};
  h.csv_name = "h_avg", h.csv_precision = 10;
  seconds.csv_name = "median_seconds", seconds.csv_precision = 4;
  ConvergenceTable t;
  for (const auto& [name, style] :
       std::vector<std::pair<std::string, ColumnStyle>>{{"mesh", plain},
                                                        {"level", count},
                                                        {"h_avg [m]", h},
                                                        {"runs", count},
                                                        {"fragments", text_only},
                                                        {"fragments_mean", csv_only},
                                                        {"fragments_sd", csv_only},
                                                        {"largest fragment / mass", text_only},
                                                        {"largest_mean", csv_only},
                                                        {"largest_sd", csv_only},
                                                        {"median run time [s]", seconds},
                                                        {"fragments_pooled",
                                                         [] {
                                                           ColumnStyle s = integer_style();
                                                           s.in_text = false;
                                                           return s;
                                                         }()},
                                                        {"KS distance to coarser (p)", text_only},
                                                        {"ks_distance", csv_only},
                                                        {"ks_p_value", csv_only}})
    t.declare_column(name, style);
  for (const FragmentLevel& l : levels) {
    t.start_row();
    t.add_text("mesh", l.mesh);
    t.add_value("level", l.level);
    t.add_value("h_avg [m]", l.h_avg);
    t.add_value("runs", static_cast<double>(l.fragments.values.size()));
    t.add_text("fragments", spread(l.fragments, 4));
    t.add_value("fragments_mean", l.fragments.mean);
    if (l.fragments.std_dev) t.add_value("fragments_sd", *l.fragments.std_dev);
    t.add_text("largest fragment / mass", spread(l.largest, 3));
    t.add_value("largest_mean", l.largest.mean);
    if (l.largest.std_dev) t.add_value("largest_sd", *l.largest.std_dev);
    t.add_value("median run time [s]", l.median_seconds);
    t.add_value("fragments_pooled", static_cast<double>(l.mass_fractions.size()));
    if (const auto& ks = l.against_coarser) {
      t.add_text("KS distance to coarser (p)",
                 fmt(ks->distance, 3) + " (" + fmt(ks->p_value, 2) + ")");
      t.add_value("ks_distance", ks->distance);
      t.add_value("ks_p_value", ks->p_value);
    }
  }
  return t;
}

}  // namespace

std::string fragment_levels_csv(const std::vector<FragmentLevel>& levels) {
  std::ostringstream csv;
  fragment_levels_table(levels).write_csv(csv, {.quote_names = false});
  return csv.str();
}

std::string fragment_levels_md(const std::vector<FragmentLevel>& levels) {
  std::ostringstream md;
  md << "\n## Over the levels\n\nComplete realizations only, coarse to fine. KS: the two-sample "
        "Kolmogorov-Smirnov distance between the pooled fragment mass fractions of a level and "
        "of the next coarser one, with its p-value (levels.csv; "
        "plots/largest_fragment_vs_h.png).\n\n";
  fragment_levels_table(levels).write_markdown(md);
  if (levels.size() < 2) return md.str();
  const KsResult& finest = *levels.back().against_coarser;
  md << "\nThe two finest levels' fragment mass distributions are "
     << (finest.p_value < kSignificance ? "distinguishable" : "not distinguishable") << " at the "
     << fmt(100 * kSignificance) << " % level (D = " << fmt(finest.distance, 3)
     << ", p = " << fmt(finest.p_value, 2) << ")";
  if (finest.p_value < kSignificance) md << ": not converged in distribution at these sizes";
  md << ". A fragment of one cell has a mass fraction of about h_avg^2 over the body's area, so "
        "distributions made of single cells move with h and cannot settle.\n";
  return md.str();
}

}  // namespace vorodg
