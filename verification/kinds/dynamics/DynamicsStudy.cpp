// The explicit-dynamics study kinds: `dynamics` (wave bars, free bodies, impacts: every measured
// figure beside its theory) and `fragmentation`, the same with crack insertion and the cohesive
// law (fragment counts, masses, the energy with the law's closed forms). One reader and one runner
// serve both. Every (mesh, level, realization) of the scene is one run (DynamicsRun) in the
// harness's resumable pool; each variant, or each value of a `perturb` study, runs into its own
// subfolder, and a perturbation study ends with the Hamming distances between them. The reports:
// results.csv (one row per run), summary.json and report.md (docs/dynamics.md "The dynamics
// study"). A run that became unstable or broke down keeps its history; the study exits 3.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/io/AtomicFile.hpp"
#include "core/util/Format.hpp"
#include "dynamics/Fragmentation.hpp"
#include "verification/harness/Ensemble.hpp"
#include "verification/harness/EnsembleStudy.hpp"
#include "verification/harness/StudyFiles.hpp"
#include "verification/harness/StudyParts.hpp"
#include "verification/kinds/dynamics/DynamicsHistory.hpp"
#include "verification/kinds/dynamics/DynamicsKeys.hpp"
#include "verification/kinds/dynamics/DynamicsMeasureFields.hpp"
#include "verification/kinds/dynamics/DynamicsRun.hpp"
#include "verification/kinds/dynamics/FragmentLevels.hpp"
#include "verification/kinds/dynamics/PerturbationReport.hpp"
#include "verification/kinds/dynamics/TimeRefinementReport.hpp"
#include "verification/report/ConvergenceTable.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace vorodg {
namespace {

/// Every field of a dynamics record, with the scene's settings that results.csv lists beside
/// them (problem, estimate, safety: not part of the record's JSON).
std::vector<RecordField<DynamicsRecord>> dynamics_fields(const DynamicsScene& scene) {
  using R = DynamicsRecord;
  const CsvFormat fine{true, 12, true};
  std::vector<RecordField<R>> f = run_id_fields<R>();
  f.insert(f.end(), {csv_column<R>("problem", scene.problem->name()), field("cells", &R::cells),
                     field("dofs", &R::dofs), field("h_avg", &R::h_avg, fine),
                     field("dt", &R::dt, fine), field("dt_critical_lanczos", &R::dt_lanczos, fine),
                     field("dt_critical_cells", &R::dt_cells, fine),
                     field("lanczos_iterations", &R::lanczos_iterations),
                     csv_column<R>("estimate", step_estimate_name(scene.estimate)),
                     csv_column<R>("safety", scene.safety), field("steps", &R::steps),
                     field("end_time", &R::end_time, fine),
                     field("contact_stiffness", &R::contact_stiffness, {true, 10, true}, true)});
  for (const auto& [name, member] : dynamics_measure_fields())  // absent: not measured
    f.push_back({name, [m = member](const R& r) { return number_json(r.measures.*m); },
                 [m = member](R& r, const json& j) { r.measures.*m = read_number(j); },
                 CsvFormat{true, 10, true}, true, true, true});
  f.push_back({"contact_steps", [](const R& r) { return json(r.measures.contact_steps); },
               [](R& r, const json& j) { r.measures.contact_steps = j.get<int>(); }});
  f.push_back({"contact_ended", [](const R& r) { return json(r.measures.contact_ended); },
               [](R& r, const json& j) { r.measures.contact_ended = j.get<bool>(); }});
  f.insert(f.end(), {field("complete", &R::complete), field("failure", &R::failure, kNotInCsv),
                     field("seconds", &R::seconds, {true, 4, false}),
                     field("loop_seconds", &R::loop_seconds, kNotInCsv)});
  // The cost of checkpointing (records from before checkpoints lack it).
  f.push_back(field("checkpoint_seconds", &R::checkpoint_seconds, kNotInCsv));
  f.back().required = false;
  return f;
}

/// The worst of a figure over the complete runs that measured it (NaN: none did).
double worst(const std::vector<DynamicsRecord>& records, double DynamicsMeasures::*field) {
  double w = NAN;
  for (const DynamicsRecord& r : records)
    if (r.complete && std::isfinite(r.measures.*field))
      w = std::isnan(w) ? std::abs(r.measures.*field) : std::max(w, std::abs(r.measures.*field));
  return w;
}

ColumnStyle digits(int precision) {
  ColumnStyle s;
  s.precision = precision;
  return s;
}

/// The table of every run: the common columns, then the problem's.
std::string runs_table(const DynamicsScene& scene, const StudyRecords<DynamicsRecord>& result) {
  const std::vector<ReportColumn> columns = scene.problem->report_columns();
  ColumnStyle blank = digits(2);  // not measured: an empty cell
  blank.missing = "";
  ConvergenceTable t;
  for (const DynamicsRecord& r : result.records) {
    const DynamicsMeasures& m = r.measures;
    t.start_row();
    t.add_text("run", r.run.id());
    t.add_value("cells", r.cells, {}, integer_style());
    t.add_value("h_avg", r.h_avg, {}, digits(4));
    t.add_value("dt [s]", r.dt, {}, digits(4));
    t.add_text("dt_crit Lanczos / cells [s]", fmt(r.dt_lanczos, 4) + " / " + fmt(r.dt_cells, 4));
    t.add_value("steps", static_cast<double>(r.steps), {}, integer_style());
    t.add_value("energy balance error", m.energy_balance_error, {}, digits(2));
    t.declare_column("momentum drift", blank);
    if (std::isfinite(m.momentum_drift)) t.add_value("momentum drift", m.momentum_drift);
    for (const ReportColumn& c : columns) t.add_text(c.header, c.cell(m));
  }
  std::ostringstream md;
  t.write_markdown(md);
  return md.str();
}

/// What the cracks did in each run of a fragmentation study.
std::string fragments_table(const StudyRecords<DynamicsRecord>& result) {
  ConvergenceTable t;
  for (const DynamicsRecord& r : result.records) {
    const DynamicsMeasures& m = r.measures;
    t.start_row();
    t.add_text("run", r.run.id());
    t.add_value("fragments", m.fragments, {}, digits(6));
    t.add_text("broken / cracked edges", fmt(m.broken_edges) + " / " + fmt(m.cracked_edges));
    t.add_value("largest fragment (mass fraction)", m.max_fragment_mass_fraction, {}, digits(3));
    t.add_value("mass in single cells", m.single_cell_mass_fraction, {}, digits(3));
    t.add_value("main body's turn [rad]", m.main_body_rotation, {}, digits(3));
    if (std::isfinite(m.broken_near_impact))
      t.add_text("broken near impact / mid-length / elsewhere",
                 fmt(m.broken_near_impact, 2) + " / " + fmt(m.broken_mid_length, 2) + " / " +
                     fmt(m.broken_elsewhere, 2));
    t.add_value("dissipated [J/m]", m.dissipated_energy, {}, digits(4));
    t.add_text(
        "balance with the law's energies",
        fmt(m.law_balance_error, 2) + (std::isfinite(m.law_balance_breach_time)
                                           ? " (past " + fmt(100 * kLawBalanceLimit) + " % at " +
                                                 fmt(m.law_balance_breach_time, 3) + " s)"
                                           : ""));
    t.add_text("largest cell rotation [rad] (first past " + fmt(kLargeRotation) + " at [s])",
               fmt(m.max_rotation, 3) + (std::isfinite(m.large_rotation_time)
                                             ? " (" + fmt(m.large_rotation_time, 3) + ")"
                                             : ""));
  }
  std::ostringstream md;
  t.write_markdown(md);
  return md.str();
}

std::string report_md(const DynamicsScene& scene, const StudyRecords<DynamicsRecord>& result) {
  std::ostringstream md;
  md << "# " << scene.name << (scene.label.empty() ? "" : " / " + scene.label) << "\n\n"
     << scene.description << "\n\nProblem " << scene.problem->name() << "; "
     << result.records.size() << " runs, " << result.incomplete
     << " incomplete. dt = " << fmt(scene.safety) << " x the " << step_estimate_name(scene.estimate)
     << " estimate of the critical step"
     << (scene.fragmentation ? ", with the cohesive springs' share (docs/fragmentation.md)" : "")
     << ".\n\n"
     << runs_table(scene, result);
  if (scene.fragmentation) md << "\n" << fragments_table(result);
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

void write_dynamics_reports(const DynamicsScene& scene, const StudyRecords<DynamicsRecord>& result,
                            const fs::path& out) {
  const std::vector<RecordField<DynamicsRecord>> fields = dynamics_fields(scene);
  write_results_csv(out, fields, result.records);
  json settings = json::object();
  for (const auto& [key, value] : scene.settings) settings[key] = value;
  json runs = json::array();
  for (const DynamicsRecord& r : result.records) {
    json j = record_json(fields, r);
    for (const char* timing : {"seconds", "loop_seconds", "check_seconds", "rebuild_seconds",
                               "coupling_seconds", "checkpoints", "checkpoint_seconds"})
      j.erase(timing);  // the same results give the same bytes, on any number of processes
    runs.push_back(j);
  }
  json summary = summary_head(scene.name, scene.fragmentation ? "fragmentation" : "dynamics");
  summary.update({{"problem", scene.problem->name()},
                  {"settings", settings},
                  {"runs", result.records.size()},
                  {"incomplete", result.incomplete},
                  {"records", runs}});
  for (const auto& [name, field] : dynamics_measure_fields())
    if (const double w = worst(result.records, field);
        std::isfinite(w) && !std::string_view(name).ends_with("seconds"))
      summary["worst"][name] = w;
  write_summary(out, summary);
  std::string md = report_md(scene, result);
  if (scene.fragmentation) {
    const std::vector<FragmentLevel> levels = fragment_levels(result.records, out);
    write_file_atomically(out / "levels.csv", fragment_levels_csv(levels));
    md += fragment_levels_md(levels);
  }
  if (!scene.statistics.quantities.empty()) {
    std::vector<json> complete;
    for (const DynamicsRecord& r : result.records)
      if (r.complete) complete.push_back(record_json(fields, r));
    if (!write_statistical_report(complete, scene.statistics, out).empty())
      md += "\nThe statistical convergence over the levels: statistical-convergence.md.\n";
  }
  write_file_atomically(out / "report.md", md);
}

StudyRecords<DynamicsRecord> run_dynamics_study(const DynamicsScene& scene, const fs::path& out,
                                                int threads, bool progress) {
  check_dynamics_meshes(scene, ensemble_runs(scene.meshes));
  StudyRecords<DynamicsRecord> result = run_study_records<DynamicsRecord>(
      scene.meshes, out, threads, progress, dynamics_fields(scene),
      [&](const EnsembleRunId& id) { return run_dynamics(scene, id, out); },
      [](const DynamicsRecord& r) {
        return r.run.id() + ": " + std::to_string(r.cells) + " cells, " + std::to_string(r.steps) +
               " steps of " + fmt(r.dt, 4) + " s, energy balance " +
               fmt(r.measures.energy_balance_error, 2) + ", " + fmt(r.seconds, 3) + " s" +
               (r.complete ? "" : " (incomplete: " + r.failure + ")");
      });
  if (Ensemble::writes_reports()) write_dynamics_reports(scene, result, out);
  return result;
}

int run_dynamics_scene(const StudyCall& call) {
  const DynamicsScene scene = read_dynamics_scene(call.scene, call.force);
  std::vector<RefinedPart> parts;  // what each part ran, for the time-refinement report
  return run_study_parts<DynamicsScene>(
      scene, call, "dynamics", "dynamics_plots.py",
      [&](const DynamicsScene& part, const std::filesystem::path& out) {
        StudyRecords<DynamicsRecord> r = run_dynamics_study(part, out, call.threads, call.progress);
        const PartCounts counts{r.records.size(), r.incomplete};
        if (!part.refinement.empty()) parts.push_back({&part, std::move(r.records), out});
        return counts;
      },
      [&](int incomplete) {
        write_time_refinement_report(scene, parts, call.out);
        if (!parts.empty() && !call.no_plots) draw_plots("time_refinement_plot.py", call.out);
        if (!scene.perturb_key.empty() && incomplete == 0)
          write_perturbation_report(scene, call.out);
        if (scene.fragmentation && scene.variants.size() >= 2 && !call.no_plots)
          draw_plots("dynamics_plots.py", call.out);  // across the variants, and the perturbation
      });
}

/// Reads as `vorodg run --force` would: --list and the fuzzer take every scene a run can take.
std::string read_dynamics(const std::string& text, const std::string& source) {
  return parse_dynamics_scene(text, source, true).description;
}

std::vector<SceneKey> dynamics_keys() {
  return dynamics_scene_keys().keys;
}

}  // namespace

nlohmann::json dynamics_record_json(const DynamicsScene& scene, const DynamicsRecord& record) {
  return record_json(dynamics_fields(scene), record);
}

StudyKind dynamics_kind() {
  return {"dynamics",
          "explicit dynamics with contact: waves, free bodies, impacts against their theory",
          read_dynamics, run_dynamics_scene, dynamics_keys};
}

StudyKind fragmentation_kind() {
  return {"fragmentation",
          "explicit dynamics with crack insertion: fragments, their masses and the energy",
          read_dynamics, run_dynamics_scene, dynamics_keys};
}

}  // namespace vorodg
