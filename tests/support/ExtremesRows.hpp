#pragma once
// Hand-made extremes sweeps and their result rows for tests/test_ExtremesStudy.cpp: a row is a
// JSON object as results.jsonl holds it (easy to vary in a test), and record() turns it into the
// typed RunRecord the verdicts read.
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "verification/kinds/extremes/ExtremesReport.hpp"
#include "verification/static/Scene.hpp"

namespace vorodg::testing {

using nlohmann::json;

/// A sweep scene made by hand: one beam, two rcp meshes, cg and dg-al with 100 iterations.
inline Scene hand_sweep(const std::string& baseline) {
  Scene s;
  s.name = "hand";
  s.axis = "kp";
  s.baseline = baseline;
  s.problems = {"beam"};
  s.domain = Rectangle(0, -0.5, 4, 0.5);
  s.nu = {0.3, 0.49};
  SceneMesh a, b;
  a.label = "first";
  a.sizes = {0.5, 0.25};
  a.perturbation = 0.1;
  b.label = "second";
  b.sizes = {0.5, 0.25};
  b.perturbation = 0.4;
  s.meshes = {a, b};
  SceneFormulation cg, al;
  cg.label = "cg";
  al.label = "dg-al";
  al.settings.formulation = "dg-al";
  al.settings.dg.max_iterations = 100;
  al.kp = {1e3};
  s.formulations = {cg, al};
  return s;
}

/// A result row as StudyRunner writes it.
inline json row(const std::string& formulation, double l2, const std::string& mesh = "first",
                int level = 0, double nu = 0.3, int realization = 0, double h_avg = 0.5) {
  const bool dg = formulation != "cg";
  const double kp = dg ? 1e3 : 0.0;
  const std::string variant = dg ? formulation + " kp=1000" : formulation;
  return {{"id", mesh + "/L" + std::to_string(level) + "/R" + std::to_string(realization) +
                     "/beam/nu=" + std::to_string(nu) + "/" + variant},
          {"mesh", mesh},
          {"level", level},
          {"realization", realization},
          {"problem", "beam"},
          {"nu", nu},
          {"formulation", formulation},
          {"variant", variant},
          {"kp", kp},
          {"status", "ok"},
          {"h_avg", h_avg},
          {"l2_error", l2},
          {"rcond", 1e-3},
          {"iterations", dg ? 3 : 1},
          {"stop_reason", dg ? "converged" : "direct"}};
}

inline json failed_row(const std::string& formulation, const std::string& error,
                       const std::string& mesh = "first") {
  json r = row(formulation, 0.0, mesh);
  for (const char* key : {"h_avg", "l2_error", "rcond", "iterations", "stop_reason"}) r.erase(key);
  r["status"] = "failed";
  r["error"] = error;
  return r;
}

/// The typed record a row stands for (the rows above are easier to vary in a test).
inline RunRecord record(const json& r) {
  RunRecord out;
  StudyRun& run = out.run;
  run.id = r["id"];
  run.mesh_label = r["mesh"];
  run.level = r["level"];
  run.size = run.level == 0 ? 0.5 : 0.25;  // hand_sweep's sizes, for both meshes
  run.realization = r["realization"];
  run.problem = r["problem"];
  run.nu = r["nu"];
  run.formulation_name = r["formulation"];
  run.formulation_label = r["formulation"];
  run.formulation = run.formulation_name == "cg" ? 0 : 1;  // hand_sweep's order
  run.variant = r["variant"];
  if (r["kp"].get<double>() > 0) run.kp = r["kp"].get<double>();
  if (r["status"] != "ok") {
    out.error = r["error"];
    return out;
  }
  RunMetrics m;
  auto number = [&](const char* key) {
    return r[key].is_number() ? r[key].get<double>() : std::nan("");
  };
  m.h_avg = number("h_avg");
  m.l2_error = number("l2_error");
  m.rcond = number("rcond");
  if (run.kp) {
    DgReport dg;
    dg.iterations = r["iterations"];
    dg.stop_reason = r["stop_reason"];
    m.dg = dg;
  }
  out.metrics = m;
  return out;
}

inline RunVerdict judge(const Scene& sweep, const json& run, const std::vector<json>& runs) {
  std::vector<RunRecord> records;
  for (const json& r : runs) records.push_back(record(r));
  return judge_run(sweep, record(run), records);
}

inline double axis(const Scene& sweep, const json& run) {
  return axis_value(sweep, record(run));
}

}  // namespace vorodg::testing
