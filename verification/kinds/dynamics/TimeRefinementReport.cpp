#include "verification/kinds/dynamics/TimeRefinementReport.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string_view>

#include "core/io/AtomicFile.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "verification/kinds/dynamics/DynamicsMeasureFields.hpp"
#include "verification/kinds/dynamics/FragmentLevels.hpp"
#include "verification/report/ConvergenceTable.hpp"
#include "verification/report/Extrapolation.hpp"

namespace vorodg {
namespace {

/// Mean and standard error of the finite values (NaN for none; the error NaN below two).
std::pair<double, double> mean_and_error(const std::vector<double>& values, int& n) {
  std::vector<double> finite;
  for (double v : values)
    if (std::isfinite(v)) finite.push_back(v);
  n = static_cast<int>(finite.size());
  if (finite.empty()) return {NAN, NAN};
  double mean = 0.0;
  for (double v : finite) mean += v / n;
  if (n < 2) return {mean, NAN};
  double ss = 0.0;
  for (double v : finite) ss += (v - mean) * (v - mean);
  return {mean, std::sqrt(ss / (n - 1) / n)};
}

/// Weighted least squares of y = a + b x with weights w: b and its standard error (from the
/// weights: the errors of y; NaN when the weights are not errors).
std::pair<double, double> weighted_slope(const std::vector<double>& x, const std::vector<double>& y,
                                         const std::vector<double>& w, bool errors) {
  double s = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    s += w[i], sx += w[i] * x[i], sy += w[i] * y[i];
    sxx += w[i] * x[i] * x[i], sxy += w[i] * x[i] * y[i];
  }
  const double d = s * sxx - sx * sx;
  if (!(d > 0.0)) return {NAN, NAN};
  return {(s * sxy - sx * sy) / d, errors ? std::sqrt(s / d) : NAN};
}

/// Monotone, with differences that shrink from step to step: a trend that settles, whose order
/// and limit mean something (a measure that grows as 1 / dt is monotone too).
bool settling(const std::vector<double>& q) {
  bool up = true, down = true, shrinking = true;
  for (std::size_t i = 1; i < q.size(); ++i) {
    up = up && q[i] > q[i - 1];
    down = down && q[i] < q[i - 1];
    if (i > 1) shrinking = shrinking && std::abs(q[i] - q[i - 1]) < std::abs(q[i - 1] - q[i - 2]);
  }
  return (up || down) && shrinking;
}

/// Whether every value at every step is the same (a setting or a constant: nothing to show).
bool constant(const std::vector<std::vector<double>>& values) {
  const double* first = nullptr;
  for (const auto& step : values)
    for (const double& v : step) {
      if (!first) first = &v;
      if (!(v == *first) && !(std::isnan(v) && std::isnan(*first))) return false;
    }
  return true;
}

}  // namespace

StepTrend step_trend(const std::vector<double>& fraction,
                     const std::vector<std::vector<double>>& values) {
  StepTrend t;
  std::vector<double> x, y, se;
  for (std::size_t i = 0; i < fraction.size(); ++i) {
    int n = 0;
    const auto [mean, error] = mean_and_error(values[i], n);
    t.fraction.push_back(fraction[i]), t.mean.push_back(mean), t.std_error.push_back(error);
    t.runs.push_back(n);
    if (std::isfinite(mean)) x.push_back(fraction[i]), y.push_back(mean), se.push_back(error);
  }
  if (x.size() < 2) return t;
  // Weighted by the errors where every step has one; a zero error (every run the same) weighs
  // as the smallest nonzero one would.
  double smallest = INFINITY;
  bool errors = true;
  for (double e : se) {
    errors = errors && std::isfinite(e);
    if (std::isfinite(e) && e > 0.0) smallest = std::min(smallest, e);
  }
  std::vector<double> w(x.size(), 1.0);
  if (errors && std::isfinite(smallest))
    for (std::size_t i = 0; i < w.size(); ++i) w[i] = 1.0 / std::pow(std::max(se[i], smallest), 2);
  std::tie(t.slope, t.slope_error) = weighted_slope(x, y, w, errors && std::isfinite(smallest));
  if (errors && !std::isfinite(smallest)) t.slope_error = 0.0;  // no spread at any step
  if (x.size() >= 3 && x.size() == fraction.size() && settling(y)) try {
      const Extrapolation e = extrapolate(x, y);
      t.order = e.rate, t.extrapolated = e.limit;
    } catch (const InputError&) {
    }
  return t;
}

namespace {

/// The refined parts of one base part, steps descending.
struct Group {
  std::string base;
  std::vector<const RefinedPart*> steps;
};

std::vector<Group> groups_of(const std::vector<RefinedPart>& parts) {
  std::vector<Group> groups;
  for (const RefinedPart& p : parts) {
    if (p.scene->refinement.empty()) continue;
    const std::string& base = p.scene->refinement_base;
    if (groups.empty() || groups.back().base != base) groups.push_back({base, {}});
    groups.back().steps.push_back(&p);
  }
  return groups;
}

/// The (mesh block, level) pairs with a complete run in every step, in run order.
std::vector<std::pair<int, int>> mesh_levels_of(const Group& g) {
  std::vector<std::pair<int, int>> out;
  for (const DynamicsRecord& r : g.steps.front()->records)
    if (r.complete &&
        std::find(out.begin(), out.end(), std::pair(r.run.mesh, r.run.level)) == out.end())
      out.emplace_back(r.run.mesh, r.run.level);
  return out;
}

std::vector<double> values_at(const RefinedPart& p, std::pair<int, int> level,
                              double DynamicsMeasures::*field) {
  std::vector<double> v;
  for (const DynamicsRecord& r : p.records)
    if (r.complete && r.run.mesh == level.first && r.run.level == level.second)
      v.push_back(r.measures.*field);
  return v;
}

std::string cell(double mean, double error, int n) {
  if (!std::isfinite(mean)) return "-";
  return fmt(mean, 4) + (std::isfinite(error) ? " ± " + fmt(error, 2) : "") + " (" +
         std::to_string(n) + ")";
}

/// Successive differences, each in units of its standard error where there is one.
std::string differences(const StepTrend& t) {
  std::string text;
  for (std::size_t i = 1; i < t.mean.size(); ++i) {
    const double d = t.mean[i] - t.mean[i - 1];
    const double e = std::hypot(t.std_error[i], t.std_error[i - 1]);
    text += (i > 1 ? "; " : "") + fmt(d, 3) +
            (std::isfinite(e) && e > 0.0 ? " (" + fmt(d / e, 2) + " SE)" : "");
  }
  return text;
}

/// The pooled fragment masses of the (mesh, level) in each step, KS between successive ones.
std::string fragment_masses(const Group& g, std::pair<int, int> level, ConvergenceTable& csv,
                            const std::string& name) {
  std::vector<std::vector<double>> pooled;
  for (const RefinedPart* p : g.steps) {
    std::vector<DynamicsRecord> here;
    for (const DynamicsRecord& r : p->records)
      if (r.complete && r.run.mesh == level.first && r.run.level == level.second) here.push_back(r);
    const std::vector<FragmentLevel> levels = fragment_levels(here, p->folder);
    pooled.push_back(levels.empty() ? std::vector<double>{} : levels.front().mass_fractions);
  }
  std::string text;
  for (std::size_t i = 1; i < pooled.size(); ++i) {
    if (pooled[i].empty() || pooled[i - 1].empty()) continue;
    const KsResult ks = ks_two_sample(pooled[i - 1], pooled[i]);
    text += "- fragment masses, x" + exact_text(g.steps[i - 1]->scene->step_fraction) + " to x" +
            exact_text(g.steps[i]->scene->step_fraction) +
            ": Kolmogorov-Smirnov D = " + fmt(ks.distance, 3) + ", p = " + fmt(ks.p_value, 2) +
            (ks.p_value < 0.05 ? " (the distributions differ at 5 %)\n" : " (not significant)\n");
    csv.start_row();
    csv.add_text("group", name);
    csv.add_value("mesh", level.first, {}, integer_style());
    csv.add_value("level", level.second, {}, integer_style());
    csv.add_text("measure", "fragment_masses_ks");
    csv.add_value("fraction", g.steps[i]->scene->step_fraction, {}, shortest_csv_style());
    csv.add_value("ks_distance", ks.distance, {}, shortest_csv_style());
    csv.add_value("ks_p_value", ks.p_value, {}, shortest_csv_style());
  }
  return text;
}

void add_csv_rows(ConvergenceTable& csv, const std::string& group, std::pair<int, int> level,
                  const char* measure, const StepTrend& t) {
  const ColumnStyle exact = shortest_csv_style();
  for (std::size_t i = 0; i < t.fraction.size(); ++i) {
    csv.start_row();
    csv.add_text("group", group);
    csv.add_value("mesh", level.first, {}, integer_style());
    csv.add_value("level", level.second, {}, integer_style());
    csv.add_text("measure", measure);
    csv.add_value("fraction", t.fraction[i], {}, exact);
    csv.add_value("runs", t.runs[i], {}, integer_style());
    for (const auto& [name, value] : {std::pair{"mean", t.mean[i]},
                                      {"std_error", t.std_error[i]},
                                      {"slope", t.slope},
                                      {"slope_error", t.slope_error},
                                      {"order", t.order},
                                      {"extrapolated", t.extrapolated}})
      if (std::isfinite(value)) csv.add_value(name, value, {}, exact);
  }
}

/// The Markdown section of one group's (mesh, level), and its CSV rows.
std::string level_section(const Group& g, std::pair<int, int> level, const std::string& name,
                          ConvergenceTable& csv) {
  std::vector<double> fractions;
  for (const RefinedPart* p : g.steps) fractions.push_back(p->scene->step_fraction);
  ConvergenceTable t;
  for (const auto& [measure, field] : dynamics_measure_fields()) {
    if (std::string_view(measure).ends_with("seconds")) continue;
    std::vector<std::vector<double>> values;
    for (const RefinedPart* p : g.steps) values.push_back(values_at(*p, level, field));
    if (constant(values)) continue;
    const StepTrend trend = step_trend(fractions, values);
    if (std::none_of(trend.mean.begin(), trend.mean.end(),
                     [](double m) { return std::isfinite(m); }))
      continue;
    add_csv_rows(csv, name, level, measure, trend);
    t.start_row();
    t.add_text("measure", measure);
    for (std::size_t i = 0; i < fractions.size(); ++i)
      t.add_text("dt0 x " + exact_text(fractions[i]) + " (runs)",
                 cell(trend.mean[i], trend.std_error[i], trend.runs[i]));
    t.add_text("differences", differences(trend));
    t.add_text("slope in the step ± SE",
               std::isfinite(trend.slope)
                   ? fmt(trend.slope, 3) +
                         (std::isfinite(trend.slope_error) ? " ± " + fmt(trend.slope_error, 2) : "")
                   : "-");
    t.add_text("observed order", std::isfinite(trend.order) ? fmt(trend.order, 2) : "-");
    t.add_text("dt -> 0", std::isfinite(trend.extrapolated) ? fmt(trend.extrapolated, 4) : "-");
  }
  const DynamicsScene& scene = *g.steps.front()->scene;
  std::ostringstream md;
  md << "\n## " << name << ", " << scene.meshes[level.first].label << " level " << level.second
     << "\n\n";
  t.write_markdown(md);
  if (scene.fragmentation) md << "\n" << fragment_masses(g, level, csv, name);
  return md.str();
}

}  // namespace

void write_time_refinement_report(const DynamicsScene& top, const std::vector<RefinedPart>& parts,
                                  const std::filesystem::path& out) {
  const std::vector<Group> groups = groups_of(parts);
  if (groups.empty()) return;
  ConvergenceTable csv;
  std::ostringstream md;
  md << "# " << top.name << ": time refinement\n\n"
     << "Each run at fractions of its step (the same meshes, seeds and physics). Per measure: "
        "the mean over the complete realizations ± its standard error (runs), the differences "
        "between successive steps (in units of their standard error), the slope of a line "
        "weighted by the errors against the step fraction (within two standard errors of zero: "
        "the measure no longer moves with the step), and, where the means are monotone over "
        "three or more steps with shrinking differences, the observed order and the value "
        "extrapolated to dt -> 0. Measures that are the same in every run are left out.\n";
  for (const Group& g : groups) {
    const std::string name = g.base.empty() ? top.name : g.base;
    for (const auto& level : mesh_levels_of(g)) md << level_section(g, level, name, csv);
  }
  write_file_atomically(out / "time-refinement.md", md.str());
  write_file_atomically(out / "time-refinement.csv", csv_text(csv));
}

}  // namespace vorodg
