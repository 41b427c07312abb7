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

Verdict judge_run(const Scene& sweep, const RunRecord& run, const std::vector<RunRecord>& runs) {
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

using Worst = std::map<std::pair<std::string, std::string>, std::map<double, Verdict>>;

std::string trust_table(const Worst& worst, json& trust) {
  std::ostringstream md;
  md << "| axis | formulation | trusted (every run ok) | nearest failure below | nearest failure "
        "above |\n"
     << "|---|---|---|---|---|\n";
  auto describe = [](double value, const Verdict& v) {
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
    md << "| " << key.first << " | " << key.second << " | " << range << " | " << below << " | "
       << above << " |\n";
    trust.push_back({{"axis", key.first},
                     {"formulation", key.second},
                     {"trusted", trusted},
                     {"nearest_failure_below", below},
                     {"nearest_failure_above", above}});
  }
  return md.str();
}

std::string csv_field(std::string s) {
  std::replace(s.begin(), s.end(), ',', ';');
  std::replace(s.begin(), s.end(), '"', '\'');
  return s;
}

/// One run's row of extremes.csv and its entry of extremes.json.
void add_case(const Scene& sweep, const RunRecord& r, const Verdict& v, double value,
              std::ostringstream& csv, json& cases) {
  const StudyRun& run = r.run;
  const auto& m = r.metrics;
  csv << sweep.name << "," << sweep.axis << "," << fmt(value, 12) << "," << run.formulation_label
      << "," << run.variant << "," << run.mesh_label << "," << run.level << "," << run.realization
      << "," << fmt(run.nu, 12) << "," << fmt(run.kp.value_or(0.0), 6) << ","
      << fmt(m ? m->h_avg : 0.0, 6) << "," << fmt(l2_error(r), 6) << ","
      << fmt(m ? m->rcond : std::nan(""), 3) << "," << (m ? m->iterations() : 0) << ","
      << (m ? m->stop_reason() : "") << "," << v.level << ",\"" << csv_field(v.reason) << "\"\n";
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
  std::ostringstream csv;
  csv << "sweep,axis,value,formulation,variant,mesh,level,realization,nu,kp,h_avg,l2_error,rcond,"
         "iterations,stop_reason,verdict,reason\n";
  json cases = json::array();
  Worst worst;  // (axis, formulation) -> value -> the worst verdict there
  int broken = 0;
  for (std::size_t s = 0; s < scene.sweeps.size(); ++s) {
    const Scene& sweep = *scene.sweeps[s];
    for (const RunRecord& r : results[s]) {
      const Verdict v = judge_run(sweep, r, results[s]);
      const double value = axis_value(sweep, r);
      broken += v.level == "broken";
      add_case(sweep, r, v, value, csv, cases);
      if (!std::isfinite(value)) continue;  // no place on the axis (cg on the k_p axis)
      Verdict& w = worst[{sweep.axis, r.run.formulation_label}][value];
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
  write_file_atomically(out / "extremes.csv", csv.str());
  write_file_atomically(out / "extremes.json", summary.dump(1) + "\n");
  markdown = md.str();
  std::cout << "\n" << table;
  return broken;
}

}  // namespace vorodg
