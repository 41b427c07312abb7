#include "verification/study/ExtremesReport.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>

#include "core/io/AtomicFile.hpp"
#include "core/util/Format.hpp"
#include "dg/DgElasticity.hpp"

namespace vorodg {
namespace {

using nlohmann::json;

constexpr double kMinRcond = 1e-12;

bool ok(const json& r) { return r.value("status", "") == "ok"; }

/// A number of a result row; NaN when absent or null (JSON has no NaN: a non-finite value
/// written to results.jsonl comes back as null).
double number(const json& r, const char* key) {
  const auto it = r.find(key);
  return it != r.end() && it->is_number() ? it->get<double>() : std::nan("");
}

/// The formulation a run belongs to in the trust table: its variant without the k_p suffix.
std::string family_of(const json& r) {
  std::string v = r.value("variant", "");
  const auto at = v.find(" kp=");
  return at == std::string::npos ? v : v.substr(0, at);
}

bool same_place(const json& a, const json& b) {
  return a["mesh"] == b["mesh"] && a["level"] == b["level"] && a["realization"] == b["realization"] &&
         a["problem"] == b["problem"];
}

/// The baseline error of a run, or NaN when the sweep has none or its baseline run failed.
double baseline_error(const Scene& sweep, const json& run, const std::vector<json>& runs) {
  const double nan = std::nan("");
  auto find = [&](auto&& match) -> const json* {
    for (const json& r : runs)
      if (match(r)) return &r;
    return nullptr;
  };
  const json* base = nullptr;
  double scale = 1.0;
  if (sweep.baseline == "first-nu") {
    base = find([&](const json& r) {
      return same_place(r, run) && r["variant"] == run["variant"] && r["nu"].get<double>() == sweep.nu.front();
    });
  } else if (sweep.baseline == "cg") {
    base = find([&](const json& r) {
      return same_place(r, run) && r["formulation"] == "cg" && r["nu"] == run["nu"];
    });
  } else if (sweep.baseline == "first-mesh") {
    base = find([&](const json& r) {
      return r["mesh"] == sweep.meshes.front().label && r["level"] == run["level"] &&
             r["realization"] == run["realization"] && r["problem"] == run["problem"] &&
             r["variant"] == run["variant"] && r["nu"] == run["nu"];
    });
  } else if (sweep.baseline == "coarsest-level") {
    base = find([&](const json& r) {
      return r["mesh"] == run["mesh"] && r["level"] == 0 && r["realization"] == run["realization"] &&
             r["problem"] == run["problem"] && r["variant"] == run["variant"] && r["nu"] == run["nu"];
    });
    if (base && ok(*base) && ok(run))
      scale = std::pow(number(run, "h_avg") / number(*base, "h_avg"), sweep.expected_rate);
  }
  if (!base || !ok(*base)) return nan;
  return scale * number(*base, "l2_error");
}

}  // namespace

double axis_value(const Scene& sweep, const json& run) {
  const auto mesh = std::find_if(sweep.meshes.begin(), sweep.meshes.end(),
                                 [&](const SceneMesh& m) { return m.label == run["mesh"]; });
  if (sweep.axis == "nu") return run["nu"];
  if (sweep.axis == "kp") return run["kp"];
  if (sweep.axis == "aspect") return sweep.domain.width() / sweep.domain.height();
  if (sweep.axis == "perturbation" && mesh != sweep.meshes.end()) return mesh->perturbation;
  if (sweep.axis == "regularization" && mesh != sweep.meshes.end()) return mesh->regularization;
  if (sweep.axis == "h" && std::isfinite(number(run, "h_avg"))) return number(run, "h_avg");
  if (sweep.axis == "h" && mesh != sweep.meshes.end()) return mesh->sizes[run["level"].get<int>()];
  return std::nan("");
}

Verdict judge_run(const Scene& sweep, const json& run, const std::vector<json>& runs) {
  if (!ok(run)) return {"broken", "breakdown: " + run.value("error", std::string("failed"))};
  const double e = number(run, "l2_error");
  if (!std::isfinite(e)) return {"broken", "non-finite error"};
  const std::string stop = run.value("stop_reason", "direct");
  if (stop != "direct" && stop != "converged")
    return {"broken", "DG iteration " + stop + " after " + std::to_string(run.value("iterations", 0)) + " steps"};
  if (e >= 1.0) return {"broken", "relative L2 error " + fmt(e, 3) + " >= 1"};
  const double base = baseline_error(sweep, run, runs);
  // Errors at round-off level (a patch test) are exact, whatever their ratio to the baseline.
  const double ratio = e <= sweep.patch_tolerance ? 1.0 : e / base;
  if (std::isfinite(ratio) && ratio > sweep.broken_factor)
    return {"broken", "error " + fmt(ratio, 3) + "x the baseline (" + sweep.baseline + ")"};
  if (std::isfinite(ratio) && ratio > sweep.degraded_factor)
    return {"degraded", "error " + fmt(ratio, 3) + "x the baseline (" + sweep.baseline + ")"};
  const double rcond = run.contains("rcond") ? number(run, "rcond") : 1.0;
  if (!(rcond >= kMinRcond)) return {"degraded", "near-singular factor (rcond " + fmt(rcond, 3) + ")"};
  int max_iterations = DgOptions{}.max_iterations;
  for (const SceneFormulation& f : sweep.formulations)
    if (f.label == family_of(run)) max_iterations = f.settings.dg.max_iterations;
  if (stop == "converged" && run.value("iterations", 0) > max_iterations / 2)
    return {"degraded", "slow DG iteration (" + std::to_string(run.value("iterations", 0)) + " steps)"};
  return {"ok", ""};
}

int write_extremes_report(const Scene& scene, const std::vector<std::vector<json>>& results,
                          const std::filesystem::path& out) {
  static const std::map<std::string, int> rank = {{"ok", 0}, {"degraded", 1}, {"broken", 2}};
  std::ostringstream csv, md;
  csv << "sweep,axis,value,formulation,variant,mesh,level,realization,nu,kp,h_avg,l2_error,rcond,"
         "iterations,stop_reason,verdict,reason\n";
  json cases = json::array();
  // (axis, formulation) -> value -> the worst verdict there.
  std::map<std::pair<std::string, std::string>, std::map<double, Verdict>> worst;
  int broken = 0;
  for (std::size_t s = 0; s < scene.sweeps.size(); ++s) {
    const Scene& sweep = *scene.sweeps[s];
    for (const json& r : results[s]) {
      const Verdict v = judge_run(sweep, r, results[s]);
      const double value = axis_value(sweep, r);
      broken += v.level == "broken";
      std::string reason = v.reason;
      std::replace(reason.begin(), reason.end(), ',', ';');
      std::replace(reason.begin(), reason.end(), '"', '\'');
      csv << sweep.name << "," << sweep.axis << "," << fmt(value, 12) << "," << family_of(r) << ","
          << r.value("variant", "") << "," << r.value("mesh", "") << "," << r.value("level", 0) << ","
          << r.value("realization", 0) << "," << fmt(r.value("nu", 0.0), 12) << ","
          << fmt(r.value("kp", 0.0), 6) << "," << fmt(r.value("h_avg", 0.0), 6) << ","
          << fmt(number(r, "l2_error"), 6) << "," << fmt(number(r, "rcond"), 3)
          << "," << r.value("iterations", 0) << "," << r.value("stop_reason", "") << "," << v.level
          << ",\"" << reason << "\"\n";
      cases.push_back({{"sweep", sweep.name}, {"axis", sweep.axis}, {"value", value},
                       {"id", r["id"]}, {"l2_error", r.contains("l2_error") ? r["l2_error"] : json()},
                       {"rcond", r.contains("rcond") ? r["rcond"] : json()}, {"iterations", r.value("iterations", 0)},
                       {"stop_reason", r.value("stop_reason", "")}, {"verdict", v.level},
                       {"reason", v.reason}});
      Verdict& w = worst[{sweep.axis, family_of(r)}][value];
      if (w.level.empty() || rank.at(v.level) > rank.at(w.level)) w = v;
    }
  }
  md << "# " << scene.name << ": numerical extremes\n\n" << scene.description << "\n\n"
     << "Each run gets a verdict: **ok**, **degraded** (error above the sweep's degraded factor times "
        "its baseline, a factor condition estimate below 1e-12, or a slow DG iteration) or "
        "**broken** (a breakdown, a non-finite or >= 100% error, a DG iteration that did not converge, "
        "or an error above the broken factor times the baseline). The table gives, per axis and "
        "formulation, the values where every run was ok and the nearest values on either side "
        "where one was not.\n\n"
     << "| axis | formulation | trusted (every run ok) | nearest failure below | nearest failure above |\n"
     << "|---|---|---|---|---|\n";
  json trust = json::array();
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
      for (std::size_t i = 0; i < trusted.size(); ++i) list << (i ? ", " : "") << fmt(trusted[i], 8);
      range = list.str();
      for (const auto& [value, v] : by_value) {
        if (v.level != "ok" && value < trusted.front()) below = describe(value, v);  // the last one below
        if (v.level != "ok" && value > trusted.front() && above == "-") above = describe(value, v);
      }
    }
    md << "| " << key.first << " | " << key.second << " | " << range << " | " << below << " | " << above << " |\n";
    trust.push_back({{"axis", key.first}, {"formulation", key.second}, {"trusted", trusted},
                     {"nearest_failure_below", below}, {"nearest_failure_above", above}});
  }
  md << "\nEvery run with its verdict and reason: extremes.csv. Each sweep's own convergence report is "
        "in its subfolder.\n\n![extremes.png](extremes.png)\n";
  const json summary = {{"scene", scene.name}, {"trust", trust}, {"cases", cases}};
  write_file_atomically(out / "extremes.csv", csv.str());
  write_file_atomically(out / "extremes.json", summary.dump(1) + "\n");
  write_file_atomically(out / "report.md", md.str());
  std::cout << "\n" << md.str().substr(md.str().find("| axis"));
  return broken;
}

}  // namespace vorodg
