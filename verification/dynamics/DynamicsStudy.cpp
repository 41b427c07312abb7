#include "verification/dynamics/DynamicsStudy.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/io/AtomicFile.hpp"
#include "core/util/Format.hpp"
#include "verification/dynamics/DynamicsHistory.hpp"
#include "verification/dynamics/FragmentLevels.hpp"
#include "verification/dynamics/FragmentationRun.hpp"
#include "verification/study/Ensemble.hpp"
#include "verification/study/ResumableRuns.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace vorodg {
namespace {

/// The measured figures by name, in the order results.csv lists them.
const std::vector<std::pair<const char*, double DynamicsMeasures::*>>& measure_fields() {
  using M = DynamicsMeasures;
  static const std::vector<std::pair<const char*, double M::*>> fields = {
      {"energy_balance_error", &M::energy_balance_error},
      {"max_energy_balance_error", &M::max_energy_balance_error},
      {"momentum_drift", &M::momentum_drift},
      {"angular_momentum_drift", &M::angular_momentum_drift},
      {"arrival_time", &M::arrival_time},
      {"arrival_theory", &M::arrival_theory},
      {"wave_speed", &M::wave_speed},
      {"wave_speed_theory", &M::wave_speed_theory},
      {"wave_speed_error", &M::wave_speed_error},
      {"max_penetration", &M::max_penetration},
      {"max_penetration_over_h", &M::max_penetration_over_h},
      {"tunnelled_contacts", &M::tunnelled_contacts},
      {"late_contacts", &M::late_contacts},
      {"impact_velocity", &M::impact_velocity},
      {"rebound_velocity", &M::rebound_velocity},
      {"rebound_estimate", &M::rebound_estimate},
      {"contact_time", &M::contact_time},
      {"contact_time_estimate", &M::contact_time_estimate},
      {"fragments", &M::fragments},
      {"max_fragment_mass_fraction", &M::max_fragment_mass_fraction},
      {"dissipated_energy", &M::dissipated_energy},
      {"cracked_edges", &M::cracked_edges},
      {"broken_edges", &M::broken_edges},
      {"released_edges", &M::released_edges},
      {"check_seconds", &M::check_seconds},
      {"rebuild_seconds", &M::rebuild_seconds},
      {"law_balance_error", &M::law_balance_error},
      {"law_balance_breach_time", &M::law_balance_breach_time},
      {"max_rotation", &M::max_rotation},
      {"large_rotation_time", &M::large_rotation_time}};
  return fields;
}

double number_or_nan(const json& j, const char* key) {
  return j.contains(key) && j.at(key).is_number() ? j.at(key).get<double>() : NAN;
}

json to_json(const DynamicsRecord& r) {
  json j = {{"id", r.run.id()},
            {"mesh", r.run.label},
            {"level", r.run.level},
            {"realization", r.run.realization},
            {"seed", r.run.seed},
            {"cells", r.cells},
            {"dofs", r.dofs},
            {"h_avg", r.h_avg},
            {"dt", r.dt},
            {"dt_critical_lanczos", r.dt_lanczos},
            {"dt_critical_cells", r.dt_cells},
            {"lanczos_iterations", r.lanczos_iterations},
            {"steps", r.steps},
            {"end_time", r.end_time},
            {"contact_steps", r.measures.contact_steps},
            {"contact_ended", r.measures.contact_ended},
            {"complete", r.complete},
            {"failure", r.failure},
            {"seconds", r.seconds},
            {"loop_seconds", r.loop_seconds}};
  for (const auto& [name, field] : measure_fields())
    if (std::isfinite(r.measures.*field)) j[name] = r.measures.*field;  // absent: not measured
  return j;
}

DynamicsRecord from_json(const json& j, const DynamicsRunId& id) {
  DynamicsRecord r;
  r.run = id;
  r.cells = j.value("cells", 0), r.dofs = j.value("dofs", 0), r.h_avg = j.value("h_avg", 0.0);
  r.dt = j.value("dt", 0.0), r.dt_lanczos = j.value("dt_critical_lanczos", 0.0);
  r.dt_cells = j.value("dt_critical_cells", 0.0);
  r.lanczos_iterations = j.value("lanczos_iterations", 0);
  r.steps = j.value("steps", 0L), r.end_time = j.value("end_time", 0.0);
  r.measures.contact_steps = j.value("contact_steps", 0);
  r.measures.contact_ended = j.value("contact_ended", true);
  r.complete = j.value("complete", false), r.failure = j.value("failure", "");
  r.seconds = j.value("seconds", 0.0), r.loop_seconds = j.value("loop_seconds", 0.0);
  for (const auto& [name, field] : measure_fields()) r.measures.*field = number_or_nan(j, name);
  return r;
}

std::string cell(double x, int precision = 6) {
  return std::isfinite(x) ? fmt(x, precision) : "";
}

std::string results_csv(const DynamicsScene& scene, const std::vector<DynamicsRecord>& records) {
  std::ostringstream csv;
  csv << "id,mesh,level,realization,problem,cells,dofs,h_avg,dt,dt_critical_lanczos,"
         "dt_critical_cells,lanczos_iterations,estimate,safety,steps,end_time";
  for (const auto& [name, field] : measure_fields()) csv << ',' << name;
  csv << ",contact_steps,contact_ended,complete,seconds\n";
  for (const DynamicsRecord& r : records) {
    csv << r.run.id() << ',' << r.run.label << ',' << r.run.level << ',' << r.run.realization << ','
        << dynamics_problem_name(scene.problem) << ',' << r.cells << ',' << r.dofs << ','
        << cell(r.h_avg, 12) << ',' << cell(r.dt, 12) << ',' << cell(r.dt_lanczos, 12) << ','
        << cell(r.dt_cells, 12) << ',' << r.lanczos_iterations << ','
        << step_estimate_name(scene.estimate) << ',' << fmt(scene.safety) << ',' << r.steps << ','
        << cell(r.end_time, 12);
    for (const auto& [name, field] : measure_fields()) csv << ',' << cell(r.measures.*field, 10);
    csv << ',' << r.measures.contact_steps << ',' << (r.measures.contact_ended ? 1 : 0) << ','
        << (r.complete ? 1 : 0) << ',' << fmt(r.seconds, 4) << '\n';
  }
  return csv.str();
}

/// The worst of a figure over the complete runs that measured it (NaN: none did).
double worst(const std::vector<DynamicsRecord>& records, double DynamicsMeasures::*field) {
  double w = NAN;
  for (const DynamicsRecord& r : records)
    if (r.complete && std::isfinite(r.measures.*field))
      w = std::isnan(w) ? std::abs(r.measures.*field) : std::max(w, std::abs(r.measures.*field));
  return w;
}

std::string report_row(const DynamicsScene& scene, const DynamicsRecord& r) {
  const DynamicsMeasures& m = r.measures;
  std::ostringstream md;
  md << "| " << r.run.id() << " | " << r.cells << " | " << fmt(r.h_avg, 4) << " | " << fmt(r.dt, 4)
     << " | " << fmt(r.dt_lanczos, 4) << " / " << fmt(r.dt_cells, 4) << " | " << r.steps << " | "
     << fmt(m.energy_balance_error, 2) << " | " << cell(m.momentum_drift, 2) << " | ";
  switch (scene.problem) {
    case DynamicsProblem::wave_bar:
      md << cell(m.arrival_time, 5) << " / " << cell(m.arrival_theory, 5) << " | "
         << cell(m.wave_speed, 5) << " / " << cell(m.wave_speed_theory, 5) << " ("
         << (std::isfinite(m.wave_speed_error) ? fmt(100 * m.wave_speed_error, 3) + "%" : "-")
         << ") |";
      break;
    case DynamicsProblem::free_body: md << cell(m.angular_momentum_drift, 2) << " |"; break;
    default:
      md << cell(m.max_penetration_over_h, 3) << " | " << cell(m.rebound_velocity, 5) << " / "
         << cell(m.rebound_estimate, 5) << " | " << cell(m.contact_time, 4) << " / "
         << cell(m.contact_time_estimate, 4) << (m.contact_ended ? "" : " (not ended)") << " |";
  }
  return md.str() + "\n";
}

std::string report_md(const DynamicsScene& scene, const DynamicsStudyResult& result) {
  std::ostringstream md;
  md << "# " << scene.name << (scene.label.empty() ? "" : " / " + scene.label) << "\n\n"
     << scene.description << "\n\nProblem " << dynamics_problem_name(scene.problem) << "; "
     << result.records.size() << " runs, " << result.incomplete
     << " incomplete. dt = " << fmt(scene.safety) << " x the " << step_estimate_name(scene.estimate)
     << " estimate of the critical step"
     << (scene.fragmentation ? ", with the cohesive springs' share (docs/fragmentation.md)" : "")
     << ".\n\n| run | cells | h_avg | dt [s] | dt_crit Lanczos / "
        "cells [s] | steps | energy balance error | momentum drift | ";
  switch (scene.problem) {
    case DynamicsProblem::wave_bar:
      md << "arrival / L/c [s] | speed / theory [m/s] "
            "|\n|---|---|---|---|---|---|---|---|---|---|\n";
      break;
    case DynamicsProblem::free_body:
      md << "angular momentum drift |\n|---|---|---|---|---|---|---|---|---|\n";
      break;
    default:
      md << "max penetration / h_avg | rebound / 1D estimate [m/s] | contact time / 2L/c_bar [s] "
            "|\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  }
  for (const DynamicsRecord& r : result.records) md << report_row(scene, r);
  if (scene.fragmentation) {
    md << "\n| run | fragments | broken / cracked edges | largest fragment (mass fraction) | "
          "dissipated [J/m] | balance with the law's energies | largest cell rotation [rad] "
          "(first past "
       << fmt(kLargeRotation) << " at [s]) |\n|---|---|---|---|---|---|---|\n";
    for (const DynamicsRecord& r : result.records) {
      const DynamicsMeasures& m = r.measures;
      md << "| " << r.run.id() << " | " << fmt(m.fragments) << " | " << fmt(m.broken_edges) << " / "
         << fmt(m.cracked_edges) << " | " << fmt(m.max_fragment_mass_fraction, 3) << " | "
         << fmt(m.dissipated_energy, 4) << " | " << fmt(m.law_balance_error, 2)
         << (std::isfinite(m.law_balance_breach_time)
                 ? " (past " + fmt(100 * kLawBalanceLimit) + " % at " +
                       fmt(m.law_balance_breach_time, 3) + " s)"
                 : "")
         << " | " << fmt(m.max_rotation, 3)
         << (std::isfinite(m.large_rotation_time) ? " (" + fmt(m.large_rotation_time, 3) + ")" : "")
         << " |\n";
    }
  }
  md << "\nEnergy balance error: |balance - balance(0)| over the input energy at the end "
        "(docs/dynamics.md). Momentum drift: max |P - P(0)| over sum m|v(0)|, only where no wall, "
        "prescribed velocity or damping acts.\n\nFiles: results.csv (one row per run), "
        "history/<run>.csv "
        "(columns "
     << DynamicsHistory::columns()
     << "), vtu/<run>.pvd (deformed mesh, velocity, cell stresses), plots/<run>_energy.png.\n";
  for (const DynamicsRecord& r : result.records)
    if (!r.complete) md << "\n- " << r.run.id() << " is incomplete: " << r.failure << "\n";
  return md.str();
}

void write_reports(const DynamicsScene& scene, const DynamicsStudyResult& result,
                   const fs::path& out) {
  write_file_atomically(out / "results.csv", results_csv(scene, result.records));
  json settings = json::object();
  for (const auto& [key, value] : scene.settings) settings[key] = value;
  json runs = json::array();
  for (const DynamicsRecord& r : result.records) {
    json j = to_json(r);
    for (const char* timing : {"seconds", "loop_seconds", "check_seconds", "rebuild_seconds"})
      j.erase(timing);  // the same results give the same bytes, on any number of processes
    runs.push_back(j);
  }
  json summary = {{"scene", scene.name},
                  {"study", scene.fragmentation ? "fragmentation" : "dynamics"},
                  {"problem", dynamics_problem_name(scene.problem)},
                  {"settings", settings},
                  {"runs", result.records.size()},
                  {"incomplete", result.incomplete},
                  {"records", runs}};
  for (const auto& [name, field] : measure_fields())
    if (const double w = worst(result.records, field);
        std::isfinite(w) && !std::string_view(name).ends_with("seconds"))
      summary["worst"][name] = w;
  write_file_atomically(out / "summary.json", summary.dump(1) + "\n");
  std::string md = report_md(scene, result);
  if (scene.fragmentation) {
    const std::vector<FragmentLevel> levels = fragment_levels(result.records, out);
    write_file_atomically(out / "levels.csv", fragment_levels_csv(levels));
    md += fragment_levels_md(levels);
  }
  write_file_atomically(out / "report.md", md);
}

}  // namespace

DynamicsStudyResult run_dynamics_study(const DynamicsScene& scene, const fs::path& out, int threads,
                                       bool progress) {
  const std::vector<DynamicsRunId> runs = dynamics_runs(scene);
  check_dynamics_meshes(scene, runs);
  fs::create_directories(out);
  std::vector<std::string> ids;
  std::vector<double> costs;
  for (const DynamicsRunId& id : runs) {
    ids.push_back(id.id());
    costs.push_back(level_cost(scene.meshes.at(id.mesh), id.level));
  }
  const auto done =
      run_resumable(ids, costs, out / "results.jsonl", threads, progress, [&](std::size_t i) {
        DynamicsRecord r;
        try {
          r = run_dynamics(scene, runs[i], out);
        } catch (const std::exception& e) {
          r.run = runs[i];
          r.failure = e.what();
        }
        return RunOutcome{to_json(r), r.run.id() + ": " + std::to_string(r.cells) + " cells, " +
                                          std::to_string(r.steps) + " steps of " + fmt(r.dt, 4) +
                                          " s, energy balance " +
                                          fmt(r.measures.energy_balance_error, 2) + ", " +
                                          fmt(r.seconds, 3) + " s" +
                                          (r.complete ? "" : " (incomplete: " + r.failure + ")")};
      });
  DynamicsStudyResult result;
  if (!Ensemble::writes_reports()) return result;  // the coordinator of a whole study
  for (const DynamicsRunId& id : runs) {
    result.records.push_back(from_json(done.at(id.id()), id));
    if (!result.records.back().complete) ++result.incomplete;
  }
  write_reports(scene, result, out);
  return result;
}

}  // namespace vorodg
