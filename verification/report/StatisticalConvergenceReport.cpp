#include "verification/report/StatisticalConvergenceReport.hpp"

#include <cctype>
#include <sstream>

#include "core/util/Format.hpp"
#include "verification/report/ConvergenceTable.hpp"

namespace vorodg {
namespace {

ColumnStyle text_only() {
  ColumnStyle s;
  s.in_csv = false;
  return s;
}

ColumnStyle csv_only() {
  return shortest_csv_style();
}

ColumnStyle csv_text_only() {
  ColumnStyle s;
  s.in_text = false;
  return s;
}

std::string interval_text(const Interval& i) {
  return fmt(i.estimate, 3) + " [" + fmt(i.low, 3) + ", " + fmt(i.high, 3) + "]";
}

/// An interval: its text in the Markdown table ("name [interval]"), its three numbers in the
/// CSV ("name", "name low", "name high").
void add_interval(ConvergenceTable& t, const std::string& name, const Interval& i) {
  t.add_text(name + " [interval]", interval_text(i), text_only());
  t.add_value(name, i.estimate, {}, csv_only());
  t.add_value(name + " low", i.low, {}, csv_only());
  t.add_value(name + " high", i.high, {}, csv_only());
}

void add_missing_interval(ConvergenceTable& t, const std::string& name) {
  t.add_text(name + " [interval]", "-", text_only());
}

/// One row per pair of successive levels of q (into a table shared by every quantity).
void add_steps(ConvergenceTable& t, const QuantityConvergence& q, bool with_name) {
  for (std::size_t k = 0; k < q.steps.size(); ++k) {
    const LevelStep& s = q.steps[k];
    t.start_row();
    if (with_name) {
      t.add_text("mesh", q.mesh, csv_text_only());
      t.add_text("quantity", q.name, csv_text_only());
    }
    t.add_value("h", q.levels[k].h_avg, {}, ColumnStyle{.precision = 3});
    t.add_value("h finer", q.levels[k + 1].h_avg, {}, ColumnStyle{.precision = 3});
    t.add_value("KS D", s.ks.distance, {}, ColumnStyle{.precision = 3});
    t.add_value("p", s.ks.p_value, {}, ColumnStyle{.precision = 2});
    t.add_value("detectable D", s.ks_critical, {}, ColumnStyle{.precision = 2});
    add_interval(t, "W1", s.wasserstein);
    add_interval(t, "mean change", s.mean_change);
    if (s.coupled) {
      t.add_value("pairs", static_cast<double>(s.coupled->pairs), {}, integer_style());
      add_interval(t, "E|D|", s.coupled->mean_absolute);
      add_interval(t, "E|D|^2", s.coupled->mean_square);
      add_interval(t, "Pr(|D| > eps)", s.coupled->exceedance);
    } else {
      for (const char* n : {"E|D|", "E|D|^2", "Pr(|D| > eps)"}) add_missing_interval(t, n);
    }
    if (!with_name || k + 1 < q.steps.size()) continue;
    for (const auto& [name, v] : {std::pair{"in distribution", &q.in_distribution},
                                  {"of the mean", &q.of_mean},
                                  {"in mean", &q.in_mean},
                                  {"in probability", &q.in_probability}})
      t.add_text(name, verdict_name(v->verdict), csv_text_only());
  }
}

/// One row per level of q (into a table shared by every quantity for the CSV).
void add_levels(ConvergenceTable& t, const QuantityConvergence& q, bool with_name) {
  for (std::size_t k = 0; k < q.levels.size(); ++k) {
    t.start_row();
    if (with_name) {
      t.add_text("mesh", q.mesh, csv_text_only());
      t.add_text("quantity", q.name, csv_text_only());
      t.add_value("level", q.levels[k].level, {}, integer_style());
    }
    t.add_value("h_avg", q.levels[k].h_avg, {}, ColumnStyle{.precision = 3});
    t.add_value("runs", static_cast<double>(q.levels[k].value.size()), {}, integer_style());
    add_interval(t, "mean", q.mean[k]);
    t.add_value("CDF band +-", q.dkw[k], {}, ColumnStyle{.precision = 2});
    t.add_value("core-hours", q.levels[k].core_seconds / 3600.0, {}, ColumnStyle{.precision = 3});
  }
}

std::string statistical_levels_table(const QuantityConvergence& q) {
  ConvergenceTable t;
  add_levels(t, q, false);
  std::ostringstream out;
  t.write_markdown(out);
  return out.str();
}

std::string verdict_lines(const QuantityConvergence& q) {
  std::string md;
  for (const auto& [name, v] : {std::pair{"In distribution", &q.in_distribution},
                                {"Of the mean", &q.of_mean},
                                {"In mean (r = 1)", &q.in_mean},
                                {"In probability", &q.in_probability}}) {
    std::string reason = v->reason;
    if (!reason.empty()) reason[0] = static_cast<char>(std::toupper(reason[0]));
    md += std::string("- **") + name + ": " + verdict_name(v->verdict) + ".** " + reason;
    if (v->realizations > 0)
      md += "; about " + std::to_string(v->realizations) + " realizations per level would decide";
    md += ".\n";
  }
  return md;
}

}  // namespace

std::string statistical_convergence_md(const std::vector<QuantityConvergence>& quantities,
                                       const StatisticalOptions& o) {
  std::string md =
      "# Statistical convergence\n\nConfidence " + fmt(o.confidence, 3) + "; tolerance " +
      fmt(o.tolerance, 3) + " of each quantity's scale; KS resolution " + fmt(o.ks_resolution, 3) +
      "; Pr(|D| > eps) at most " + fmt(o.probability, 3) + "; levels " +
      (o.coupled ? "coupled (each realization's random field shared)" : "independent") +
      " (docs/statistics.md).\n";
  for (const QuantityConvergence& q : quantities) {
    const std::string title = q.mesh.empty() ? q.name : q.mesh + ": " + q.name;
    md += "\n## " + title + "\n\n" + statistical_levels_table(q) + "\n";
    ConvergenceTable steps;
    add_steps(steps, q, false);
    std::ostringstream out;
    steps.write_markdown(out);
    md += out.str() + "\nScale " + fmt(q.scale, 3) + ", eps " + fmt(q.epsilon, 3) +
          (q.trend ? "; over the " + std::to_string(q.levels.size()) +
                         " levels the mean goes as h^" + fmt(*q.trend, 2)
                   : "") +
          ".\n\n" + verdict_lines(q);
  }
  return md;
}

std::string statistical_convergence_csv(const std::vector<QuantityConvergence>& quantities) {
  ConvergenceTable t;
  for (const QuantityConvergence& q : quantities) add_steps(t, q, true);
  return csv_text(t);
}

std::string statistical_levels_csv(const std::vector<QuantityConvergence>& quantities) {
  ConvergenceTable t;
  for (const QuantityConvergence& q : quantities) add_levels(t, q, true);
  return csv_text(t);
}

}  // namespace vorodg
