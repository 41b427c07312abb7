#include "verification/kinds/dynamics/FragmentLevels.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"

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

std::string fragment_levels_csv(const std::vector<FragmentLevel>& levels) {
  std::ostringstream csv;
  csv << "mesh,level,h_avg,runs,fragments_mean,fragments_sd,largest_mean,largest_sd,"
         "median_seconds,fragments_pooled,ks_distance,ks_p_value\n";
  auto sd = [](const SampleStatistics& s) { return s.std_dev ? fmt(*s.std_dev, 10) : ""; };
  for (const FragmentLevel& l : levels) {
    csv << l.mesh << ',' << l.level << ',' << fmt(l.h_avg, 10) << ',' << l.fragments.values.size()
        << ',' << fmt(l.fragments.mean, 10) << ',' << sd(l.fragments) << ','
        << fmt(l.largest.mean, 10) << ',' << sd(l.largest) << ',' << fmt(l.median_seconds, 4) << ','
        << l.mass_fractions.size() << ',';
    if (l.against_coarser)
      csv << fmt(l.against_coarser->distance, 10) << ',' << fmt(l.against_coarser->p_value, 10);
    else
      csv << ',';
    csv << '\n';
  }
  return csv.str();
}

std::string fragment_levels_md(const std::vector<FragmentLevel>& levels) {
  std::ostringstream md;
  md << "\n## Over the levels\n\nComplete realizations only, coarse to fine. KS: the two-sample "
        "Kolmogorov-Smirnov distance between the pooled fragment mass fractions of a level and "
        "of the next coarser one, with its p-value (levels.csv; "
        "plots/largest_fragment_vs_h.png).\n\n| mesh | level | h_avg [m] | runs | fragments | "
        "largest fragment / mass | median run time [s] | KS distance to coarser (p) "
        "|\n|---|---|---|---|---|---|---|---|\n";
  for (const FragmentLevel& l : levels) {
    md << "| " << l.mesh << " | " << l.level << " | " << fmt(l.h_avg, 4) << " | "
       << l.fragments.values.size() << " | " << spread(l.fragments, 4) << " | "
       << spread(l.largest, 3) << " | " << fmt(l.median_seconds, 3) << " | ";
    if (l.against_coarser)
      md << fmt(l.against_coarser->distance, 3) << " (" << fmt(l.against_coarser->p_value, 2)
         << ")";
    else
      md << "-";
    md << " |\n";
  }
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
