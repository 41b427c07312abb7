#include "verification/kinds/extremes/ExtremesReport.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/io/AtomicFile.hpp"
#include "core/util/Format.hpp"
#include "dg/DgElasticity.hpp"
#include "verification/report/ConvergenceTable.hpp"

namespace vorodg {
namespace {

using nlohmann::json;

constexpr double kMinRcond = 1e-12;

double l2_error(const RunRecord& r) {
  return r.metrics ? r.metrics->l2_error : std::nan("");
}

bool same_place(const StudyRun& a, const StudyRun& b) {
  return a.mesh_label == b.mesh_label && a.level == b.level && a.realization == b.realization &&
         a.problem == b.problem;
}

/// The run of `runs` a run of the sweep is compared with (nullptr if none).
const RunRecord* baseline_run(const Scene& sweep, const StudyRun& run,
                              const std::vector<RunRecord>& runs) {
  auto find = [&](auto&& match) -> const RunRecord* {
    for (const RunRecord& r : runs)
      if (match(r.run)) return &r;
    return nullptr;
  };
  if (sweep.baseline == "first-nu")
    return find([&](const StudyRun& r) {
      return same_place(r, run) && r.variant == run.variant && r.nu == sweep.nu.front();
    });
  if (sweep.baseline == "cg")
    return find([&](const StudyRun& r) {
      return same_place(r, run) && r.formulation_name == "cg" && r.nu == run.nu;
    });
  if (sweep.baseline == "first-mesh")
    return find([&](const StudyRun& r) {
      return r.mesh_label == sweep.meshes.front().label && r.level == run.level &&
             r.realization == run.realization && r.problem == run.problem &&
             r.variant == run.variant && r.nu == run.nu;
    });
  if (sweep.baseline == "coarsest-level")
    return find([&](const StudyRun& r) {
      return r.mesh_label == run.mesh_label && r.level == 0 && r.realization == run.realization &&
             r.problem == run.problem && r.variant == run.variant && r.nu == run.nu;
    });
  return nullptr;
}

/// The baseline error of a run, or NaN when the sweep has none or its baseline run failed.
double baseline_error(const Scene& sweep, const RunRecord& run,
                      const std::vector<RunRecord>& runs) {
  const RunRecord* base = baseline_run(sweep, run.run, runs);
  if (!base || !base->ok()) return std::nan("");
  double scale = 1.0;
  if (sweep.baseline == "coarsest-level" && run.ok())
    scale = std::pow(run.metrics->h_avg / base->metrics->h_avg, sweep.expected_rate);
  return scale * base->metrics->l2_error;
}

int allowed_iterations(const Scene& sweep, const StudyRun& run) {
  return run.formulation < static_cast<int>(sweep.formulations.size())
             ? sweep.formulations[run.formulation].settings.dg.max_iterations
             : DgOptions{}.max_iterations;
}

}  // namespace

double axis_value(const Scene& sweep, const RunRecord& record) {
  const StudyRun& run = record.run;
  const auto mesh = std::find_if(sweep.meshes.begin(), sweep.meshes.end(),
                                 [&](const SceneMesh& m) { return m.label == run.mesh_label; });
  if (sweep.axis == "nu") return run.nu;
  if (sweep.axis == "kp") return run.kp.value_or(std::nan(""));
  if (sweep.axis == "aspect") return sweep.domain.width() / sweep.domain.height();
  if (sweep.axis == "perturbation" && mesh != sweep.meshes.end()) return mesh->perturbation;
  if (sweep.axis == "regularization" && mesh != sweep.meshes.end()) return mesh->regularization;
  if (sweep.axis == "h" && record.metrics && std::isfinite(record.metrics->h_avg))
    return record.metrics->h_avg;
  if (sweep.axis == "h") return run.size;
  return std::nan("");
}

RunVerdict judge_run(const Scene& sweep, const RunRecord& run, const std::vector<RunRecord>& runs) {
  if (!run.ok()) return {"broken", "breakdown: " + run.error};
  const RunMetrics& m = *run.metrics;
  const double e = m.l2_error;
  if (!std::isfinite(e)) return {"broken", "non-finite error"};
  const std::string stop = m.stop_reason();
  if (stop != "direct" && stop != "converged")
    return {"broken",
            "DG iteration " + stop + " after " + std::to_string(m.iterations()) + " steps"};
  if (e >= 1.0) return {"broken", "relative L2 error " + fmt(e, 3) + " >= 1"};
  const double base = baseline_error(sweep, run, runs);
  // Errors at round-off level (a patch test) are exact, whatever their ratio to the baseline.
  const double ratio = e <= sweep.patch_tolerance ? 1.0 : e / base;
  if (std::isfinite(ratio) && ratio > sweep.broken_factor)
    return {"broken", "error " + fmt(ratio, 3) + "x the baseline (" + sweep.baseline + ")"};
  if (std::isfinite(ratio) && ratio > sweep.degraded_factor)
    return {"degraded", "error " + fmt(ratio, 3) + "x the baseline (" + sweep.baseline + ")"};
  if (!(m.rcond >= kMinRcond))
    return {"degraded", "near-singular factor (rcond " + fmt(m.rcond, 3) + ")"};
  if (stop == "converged" && m.iterations() > allowed_iterations(sweep, run.run) / 2)
    return {"degraded", "slow DG iteration (" + std::to_string(m.iterations()) + " steps)"};
  return {"ok", ""};
}

namespace {

using Worst = std::map<std::pair<std::string, std::string>, std::map<double, RunVerdict>>;

std::string trust_table(const Worst& worst, json& trust) {
  ConvergenceTable t;
  auto describe = [](double value, const RunVerdict& v) {
    return fmt(value, 8) + ": " + v.level + ", " + v.reason;
  };
  for (const auto& [key, by_value] : worst) {
    std::vector<double> trusted;
    for (const auto& [value, v] : by_value)
      if (v.level == "ok") trusted.push_back(value);
    std::string below = "-", above = "-", range = "none";
    if (trusted.empty()) {
      below = describe(by_value.begin()->first, by_value.begin()->second);
    } else {
      std::ostringstream list;
      for (std::size_t i = 0; i < trusted.size(); ++i)
        list << (i ? ", " : "") << fmt(trusted[i], 8);
      range = list.str();
      for (const auto& [value, v] : by_value) {
        if (v.level != "ok" && value < trusted.front())
          below = describe(value, v);  // the last one below
        if (v.level != "ok" && value > trusted.front() && above == "-") above = describe(value, v);
      }
    }
    t.start_row();
    t.add_text("axis", key.first);
    t.add_text("formulation", key.second);
    t.add_text("trusted (every run ok)", range);
    t.add_text("nearest failure below", below);
    t.add_text("nearest failure above", above);
    trust.push_back({{"axis", key.first},
                     {"formulation", key.second},
                     {"trusted", trusted},
                     {"nearest_failure_below", below},
                     {"nearest_failure_above", above}});
  }
  std::ostringstream md;
  t.write_markdown(md);
  return md.str();
}

/// The columns of extremes.csv, in order, with their digits.
ConvergenceTable extremes_table() {
  ColumnStyle plain;
  plain.csv_quoted = false;
  const auto digits = [&](int n) {
    ColumnStyle s = plain;
    s.csv_precision = n;
    return s;
  };
  ConvergenceTable t;
  for (const auto& [name, style] :
       std::vector<std::pair<std::string, ColumnStyle>>{{"sweep", plain},
                                                        {"axis", plain},
                                                        {"value", digits(12)},
                                                        {"formulation", plain},
                                                        {"variant", plain},
                                                        {"mesh", plain},
                                                        {"level", plain},
                                                        {"realization", plain},
                                                        {"nu", digits(12)},
                                                        {"kp", digits(6)},
                                                        {"h_avg", digits(6)},
                                                        {"l2_error", digits(6)},
                                                        {"rcond", digits(3)},
                                                        {"iterations", plain},
                                                        {"stop_reason", plain},
                                                        {"verdict", plain},
                                                        {"reason", ColumnStyle{}}})
    t.declare_column(name, style);
  return t;
}

/// One run's row of extremes.csv and its entry of extremes.json.
void add_case(const Scene& sweep, const RunRecord& r, const RunVerdict& v, double value,
              ConvergenceTable& csv, json& cases) {
  const StudyRun& run = r.run;
  const auto& m = r.metrics;
  std::string reason = v.reason;  // one quoted cell: no commas or double quotes inside
  std::replace(reason.begin(), reason.end(), ',', ';');
  std::replace(reason.begin(), reason.end(), '"', '\'');
  csv.start_row();
  csv.add_text("sweep", sweep.name);
  csv.add_text("axis", sweep.axis);
  csv.add_value("value", value);
  csv.add_text("formulation", run.formulation_label);
  csv.add_text("variant", run.variant);
  csv.add_text("mesh", run.mesh_label);
  csv.add_text("level", std::to_string(run.level));
  csv.add_text("realization", std::to_string(run.realization));
  csv.add_value("nu", run.nu);
  csv.add_value("kp", run.kp.value_or(0.0));
  csv.add_value("h_avg", m ? m->h_avg : 0.0);
  csv.add_value("l2_error", l2_error(r));
  csv.add_value("rcond", m ? m->rcond : std::nan(""));
  csv.add_text("iterations", std::to_string(m ? m->iterations() : 0));
  csv.add_text("stop_reason", m ? m->stop_reason() : "");
  csv.add_text("verdict", v.level);
  csv.add_text("reason", reason);
  cases.push_back({{"sweep", sweep.name},
                   {"axis", sweep.axis},
                   {"value", value},
                   {"id", run.id},
                   {"l2_error", m ? json(m->l2_error) : json()},
                   {"rcond", m ? json(m->rcond) : json()},
                   {"iterations", m ? m->iterations() : 0},
                   {"stop_reason", m ? m->stop_reason() : ""},
                   {"verdict", v.level},
                   {"reason", v.reason}});
}

}  // namespace

int write_extremes_report(const Scene& scene, const std::vector<std::vector<RunRecord>>& results,
                          const std::filesystem::path& out, std::string& markdown) {
  static const std::map<std::string, int> rank = {{"ok", 0}, {"degraded", 1}, {"broken", 2}};
  ConvergenceTable csv = extremes_table();
  json cases = json::array();
  Worst worst;  // (axis, formulation) -> value -> the worst verdict there
  int broken = 0;
  for (std::size_t s = 0; s < scene.sweeps.size(); ++s) {
    const Scene& sweep = *scene.sweeps[s];
    for (const RunRecord& r : results[s]) {
      const RunVerdict v = judge_run(sweep, r, results[s]);
      const double value = axis_value(sweep, r);
      broken += v.level == "broken";
      add_case(sweep, r, v, value, csv, cases);
      if (!std::isfinite(value)) continue;  // no place on the axis (cg on the k_p axis)
      RunVerdict& w = worst[{sweep.axis, r.run.formulation_label}][value];
      if (w.level.empty() || rank.at(v.level) > rank.at(w.level)) w = v;
    }
  }
  json trust = json::array();
  const std::string table = trust_table(worst, trust);
  std::ostringstream md;
  md << "# " << scene.name << ": numerical extremes\n\n"
     << scene.description << "\n\n"
     << "Each run gets a verdict: **ok**, **degraded** (error above the sweep's degraded factor "
        "times "
        "its baseline, a factor condition estimate below 1e-12, or a slow DG iteration) or "
        "**broken** (a breakdown, a non-finite or >= 100% error, a DG iteration that did not "
        "converge, "
        "or an error above the broken factor times the baseline). The table gives, per axis and "
        "formulation, the values where every run was ok and the nearest values on either side "
        "where one was not.\n\n"
     << table
     << "\nEvery run with its verdict and reason: extremes.csv. Each sweep's own convergence "
        "report is "
        "in its subfolder.\n\n";
  const json summary = {{"scene", scene.name}, {"trust", trust}, {"cases", cases}};
  std::ostringstream csv_text;
  csv.write_csv(csv_text, {.quote_names = false});
  write_file_atomically(out / "extremes.csv", csv_text.str());
  write_file_atomically(out / "extremes.json", summary.dump(1) + "\n");
  markdown = md.str();
  std::cout << "\n" << table;
  return broken;
}

}  // namespace vorodg
