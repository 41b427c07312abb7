// The fracture study kind: cohesive crack growth along a quasi-static load path. Every (mesh,
// level, realization) of the scene is one run (FractureRun) in the harness's resumable pool; each
// variant runs into its own subfolder. The reports are written from the records: results.csv (one
// row per run), summary.json and report.md with, per level, the statistics of peak load,
// dissipated energy and crack length and the two-sample Kolmogorov-Smirnov distance between
// successive levels (docs/fracture.md "Statistics"). A run whose path could not be followed to
// its end keeps its converged points; the study then exits 3.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/io/AtomicFile.hpp"
#include "core/util/Format.hpp"
#include "verification/harness/Ensemble.hpp"
#include "verification/harness/EnsembleStudy.hpp"
#include "verification/harness/StudyFiles.hpp"
#include "verification/harness/StudyParts.hpp"
#include "verification/kinds/fracture/FractureKeys.hpp"
#include "verification/kinds/fracture/FractureRun.hpp"
#include "verification/report/ConvergenceTable.hpp"
#include "verification/report/Extrapolation.hpp"
#include "verification/report/KolmogorovSmirnov.hpp"
#include "verification/report/SampleStatistics.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace vorodg {
namespace {

/// Every field of a fracture record: its JSON line and its results.csv columns.
const std::vector<RecordField<FractureRecord>>& fracture_fields() {
  using R = FractureRecord;
  static const std::vector<RecordField<R>> fields = [] {
    const CsvFormat fine{true, 12, false};
    std::vector<RecordField<R>> f = run_id_fields<R>();
    f.insert(f.end(), {field("cells", &R::cells), field("dofs", &R::dofs),
                       field("full_dg_dofs", &R::full_dg_dofs), field("h_avg", &R::h_avg, fine),
                       field("peak_load", &R::peak_load, fine),
                       field("displacement_at_peak", &R::displacement_at_peak, fine),
                       field("load_at_twice_peak", &R::load_at_twice_peak, {true, 12, true}, true),
                       field("dissipated_energy", &R::dissipated_energy, fine),
                       field("crack_length", &R::crack_length, fine),
                       field("crack_tortuosity", &R::crack_tortuosity, {true, 12, true}, true),
                       field("energy_balance_error", &R::energy_balance_error),
                       field("closed_form_error", &R::closed_form_error, {true, 6, true}, true),
                       field("points", &R::points, kNotInCsv),
                       field("newton_iterations", &R::newton_iterations, kNotInCsv),
                       field("factorizations", &R::factorizations, kNotInCsv),
                       field("complete", &R::complete), field("failure", &R::failure, kNotInCsv),
                       field("ended", &R::ended, kNotInCsv), field("seconds", &R::seconds)});
    return f;
  }();
  return fields;
}

struct LevelStats {
  std::string mesh;
  int level = 0;
  double h_avg = 0.0;
  std::vector<double> peak, dissipated, crack;
};

std::vector<LevelStats> by_level(const std::vector<FractureRecord>& records) {
  std::vector<LevelStats> levels;
  for (const FractureRecord& r : records) {
    if (!r.complete) continue;
    if (levels.empty() || levels.back().mesh != r.run.label || levels.back().level != r.run.level)
      levels.push_back({r.run.label, r.run.level, 0.0, {}, {}, {}});
    LevelStats& l = levels.back();
    l.h_avg += r.h_avg;
    l.peak.push_back(r.peak_load);
    l.dissipated.push_back(r.dissipated_energy);
    l.crack.push_back(r.crack_length);
  }
  for (LevelStats& l : levels) l.h_avg /= static_cast<double>(l.peak.size());
  return levels;
}

json sample_json(const std::vector<double>& v) {
  const SampleStatistics s = sample_statistics(v);
  json j = {{"mean", s.mean}, {"min", s.min}, {"max", s.max}, {"values", v}};
  if (s.std_dev) j["std_dev"] = *s.std_dev;
  return j;
}

/// Per mesh with at least three levels: the mean peak load extrapolated to h -> 0 (the observed
/// order of convergence and the limit), into the summary and as report text.
std::string peak_extrapolation(const std::vector<LevelStats>& levels, json& summary) {
  std::map<std::string, std::pair<std::vector<double>, std::vector<double>>> by_mesh;
  for (const LevelStats& l : levels) {
    by_mesh[l.mesh].first.push_back(l.h_avg);
    by_mesh[l.mesh].second.push_back(sample_statistics(l.peak).mean);
  }
  std::ostringstream md;
  for (const auto& [mesh, hq] : by_mesh) {
    if (hq.first.size() < 3) continue;
    const Extrapolation e = extrapolate(hq.first, hq.second);
    summary["peak_load_extrapolation"][mesh] = {{"limit", e.limit},
                                                {"rate", e.rate},
                                                {"coefficient", e.coefficient},
                                                {"residual", e.residual}};
    md << "\nMean peak load on " << mesh << ", fitted as P(h) = P0 + c h^p over the "
       << hq.first.size() << " levels: P0 = " << fmt(e.limit, 5) << " N, p = " << fmt(e.rate, 3)
       << " (rms misfit " << fmt(e.residual, 3) << " N).\n";
  }
  return md.str();
}

/// The two-sample KS distance and p-value of each figure between a level and the one before.
json ks_to_previous(const LevelStats& now, const LevelStats& before) {
  json ks = json::object();
  for (const auto& [name, a, b] :
       {std::tuple{"peak_load", &now.peak, &before.peak},
        std::tuple{"dissipated_energy", &now.dissipated, &before.dissipated},
        std::tuple{"crack_length", &now.crack, &before.crack}}) {
    const KsResult k = ks_two_sample(*a, *b);
    ks[name] = {{"distance", k.distance}, {"p_value", k.p_value}};
  }
  return ks;
}

/// Per level: the statistics into the summary's "levels" and one row of the report's table.
json level_statistics(const std::vector<LevelStats>& levels, ConvergenceTable& table) {
  json out = json::array();
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const LevelStats& l = levels[i];
    json j = {{"mesh", l.mesh},
              {"level", l.level},
              {"h_avg", l.h_avg},
              {"peak_load", sample_json(l.peak)},
              {"dissipated_energy", sample_json(l.dissipated)},
              {"crack_length", sample_json(l.crack)}};
    std::string ks_text = "-";
    if (i > 0 && levels[i - 1].mesh == l.mesh) {
      j["ks_to_previous"] = ks_to_previous(l, levels[i - 1]);
      const json& peak = j["ks_to_previous"]["peak_load"];
      ks_text =
          fmt(peak["distance"].get<double>(), 3) + ", " + fmt(peak["p_value"].get<double>(), 3);
    }
    out.push_back(j);
    const SampleStatistics p = sample_statistics(l.peak);
    table.start_row();
    table.add_text("mesh", l.mesh);
    table.add_value("level", l.level);
    table.add_value("h_avg", l.h_avg);
    table.add_value("runs", static_cast<double>(l.peak.size()));
    table.add_value("peak load [N] (mean ± sd)", p.mean, p.std_dev, {5, false, 3});
    table.add_value("dissipated [J]", sample_statistics(l.dissipated).mean, {}, {5});
    table.add_value("crack length [m]", sample_statistics(l.crack).mean, {}, {4});
    table.add_text("KS(peak) vs previous level (D, p)", ks_text);
  }
  return out;
}

/// The worst closed-form (tension bar) and energy-balance errors, into the summary and report.
std::string worst_errors(const std::vector<FractureRecord>& records, json& summary) {
  std::ostringstream md;
  double worst_closed_form = NAN, worst = 0.0;
  for (const FractureRecord& r : records) {
    if (!std::isnan(r.closed_form_error))
      worst_closed_form = std::isnan(worst_closed_form)
                              ? r.closed_form_error
                              : std::max(worst_closed_form, r.closed_form_error);
    worst = std::max(worst, r.energy_balance_error);
  }
  if (!std::isnan(worst_closed_form)) {
    summary["worst_closed_form_error"] = worst_closed_form;
    md << "\nLargest deviation from the tension bar's closed form over every converged point: "
       << fmt(worst_closed_form, 3) << " (load over sigma_c H t, stroke relative).\n";
  }
  summary["worst_energy_balance_error"] = worst;
  md << "\nWorst energy balance error over every converged point of every run: " << fmt(worst, 3)
     << " of the external work.\n";
  return md.str();
}

void write_fracture_reports(const FractureScene& scene, const StudyRecords<FractureRecord>& result,
                            const fs::path& out) {
  write_results_csv(out, fracture_fields(), result.records);

  const std::string problem = scene.geometry.problem->name();
  const std::string mode = cracking_mode_name(scene.mode);
  const std::string control = load_control_name(scene.loading.control);
  json summary = summary_head(scene.name, "fracture");
  summary.update({{"problem", problem},
                  {"mode", mode},
                  {"control", control},
                  {"runs", result.records.size()},
                  {"incomplete", result.incomplete}});
  // The expected dissipation once the ligament is fully cracked: G x ligament x thickness.
  const double ligament = scene.geometry.domain.height() - scene.geometry.notch_depth;
  summary["full_separation_energy"] = scene.law.fracture_energy * ligament * scene.thickness;
  std::ostringstream md;
  md << "# " << scene.name << (scene.label.empty() ? "" : " / " + scene.label) << "\n\n"
     << scene.description << "\n\nProblem " << problem << ", cracking " << mode << ", control "
     << control << "; " << result.records.size() << " runs, " << result.incomplete
     << " incomplete.\n\n";
  const std::vector<LevelStats> levels = by_level(result.records);
  ConvergenceTable table;
  summary["levels"] = level_statistics(levels, table);
  if (levels.empty())
    md << "No run is complete: no statistics per level.\n";
  else
    table.write_markdown(md);
  md << peak_extrapolation(levels, summary) << worst_errors(result.records, summary)
     << "\nFiles: results.csv (one row per run), curves/<run>.csv (one row per converged point), "
        "cracks/<run>.csv (faces past the strength), vtu/<run>.pvd (deformed mesh, magnified, "
        "with interface states).\n";
  for (const FractureRecord& r : result.records) {
    if (!r.complete) md << "\n- " << r.run.id() << " is incomplete: " << r.failure << "\n";
    if (!r.ended.empty()) md << "\n- " << r.run.id() << " ended early: " << r.ended << "\n";
  }
  if (!scene.statistics.quantities.empty()) {
    std::vector<json> complete;
    for (const FractureRecord& r : result.records)
      if (r.complete) complete.push_back(record_json(fracture_fields(), r));
    if (!write_statistical_report(complete, scene.statistics, out).empty())
      md << "\nThe statistical convergence over the levels: statistical-convergence.md.\n";
  }
  write_summary(out, summary);
  write_file_atomically(out / "report.md", md.str());
}

StudyRecords<FractureRecord> run_fracture_study(const FractureScene& scene, const fs::path& out,
                                                int threads, bool progress) {
  check_fracture_meshes(scene, ensemble_runs(scene.meshes));
  StudyRecords<FractureRecord> result = run_study_records<FractureRecord>(
      scene.meshes, out, threads, progress, fracture_fields(),
      [&](const EnsembleRunId& id) { return run_fracture(scene, id, out); },
      [](const FractureRecord& r) {
        return r.run.id() + ": peak " + fmt(r.peak_load, 5) + " N, " + std::to_string(r.points) +
               " points, " + fmt(r.seconds, 3) + " s" +
               (r.complete ? "" : " (incomplete: " + r.failure + ")") +
               (r.ended.empty() ? "" : " (ended: " + r.ended + ")");
      });
  if (Ensemble::writes_reports()) write_fracture_reports(scene, result, out);
  return result;
}

int run_fracture_scene(const StudyCall& call) {
  return run_study_parts<FractureScene>(
      read_fracture_scene(call.scene), call, "fracture", "fracture_plots.py",
      [&](const FractureScene& part, const std::filesystem::path& out) {
        const StudyRecords<FractureRecord> r =
            run_fracture_study(part, out, call.threads, call.progress);
        return PartCounts{r.records.size(), r.incomplete};
      });
}

}  // namespace

nlohmann::json fracture_record_json(const FractureRecord& record) {
  return record_json(fracture_fields(), record);
}

std::vector<std::string> fracture_record_numbers() {
  return number_field_names(fracture_fields());
}

StudyKind fracture_kind() {
  return {"fracture",
          "cohesive crack growth along a load path: curves, cracks, distributions per level",
          [](const std::string& text, const std::string& source) {
            return parse_fracture_scene(text, source).description;
          },
          run_fracture_scene, [] { return fracture_scene_keys().keys; }};
}

}  // namespace vorodg
