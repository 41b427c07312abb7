#include "verification/fracture/FractureStudy.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/io/AtomicFile.hpp"
#include "core/util/Format.hpp"
#include "verification/harness/EnsembleStudy.hpp"
#include "verification/report/Extrapolation.hpp"
#include "verification/report/KolmogorovSmirnov.hpp"
#include "verification/report/SampleStatistics.hpp"
#include "verification/study/Ensemble.hpp"

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
                       field("dissipated_energy", &R::dissipated_energy, fine),
                       field("crack_length", &R::crack_length, fine),
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

json stats_json(const std::vector<double>& v) {
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

void write_reports(const FractureScene& scene, const FractureStudyResult& result,
                   const fs::path& out) {
  std::string csv = csv_header(fracture_fields());
  for (const FractureRecord& r : result.records) csv += csv_row(fracture_fields(), r);
  write_file_atomically(out / "results.csv", csv);

  const std::vector<LevelStats> levels = by_level(result.records);
  json summary = {{"scene", scene.name},
                  {"study", "fracture"},
                  {"problem", fracture_problem_name(scene.geometry.kind)},
                  {"mode", cracking_mode_name(scene.mode)},
                  {"control", load_control_name(scene.loading.control)},
                  {"runs", result.records.size()},
                  {"incomplete", result.incomplete}};
  // The expected dissipation once the ligament is fully cracked: G x ligament x thickness.
  const double ligament = scene.geometry.domain.height() - scene.geometry.notch_depth;
  summary["full_separation_energy"] = scene.law.fracture_energy * ligament * scene.thickness;
  std::ostringstream md;
  md << "# " << scene.name << (scene.label.empty() ? "" : " / " + scene.label) << "\n\n"
     << scene.description << "\n\nProblem " << fracture_problem_name(scene.geometry.kind)
     << ", cracking " << cracking_mode_name(scene.mode) << ", control "
     << load_control_name(scene.loading.control) << "; " << result.records.size() << " runs, "
     << result.incomplete << " incomplete.\n\n"
     << "| mesh | level | h_avg | runs | peak load [N] (mean ± sd) | dissipated [J] | crack "
        "length [m] | KS(peak) vs previous level (D, p) |\n|---|---|---|---|---|---|---|---|\n";
  json out_levels = json::array();
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const LevelStats& l = levels[i];
    json j = {{"mesh", l.mesh},
              {"level", l.level},
              {"h_avg", l.h_avg},
              {"peak_load", stats_json(l.peak)},
              {"dissipated_energy", stats_json(l.dissipated)},
              {"crack_length", stats_json(l.crack)}};
    std::string ks_text = "-";
    if (i > 0 && levels[i - 1].mesh == l.mesh) {
      json ks = json::object();
      for (const auto& [name, now, before] :
           {std::tuple{"peak_load", &l.peak, &levels[i - 1].peak},
            std::tuple{"dissipated_energy", &l.dissipated, &levels[i - 1].dissipated},
            std::tuple{"crack_length", &l.crack, &levels[i - 1].crack}}) {
        const KsResult k = ks_two_sample(*now, *before);
        ks[name] = {{"distance", k.distance}, {"p_value", k.p_value}};
      }
      j["ks_to_previous"] = ks;
      ks_text = fmt(ks["peak_load"]["distance"].get<double>(), 3) + ", " +
                fmt(ks["peak_load"]["p_value"].get<double>(), 3);
    }
    out_levels.push_back(j);
    const SampleStatistics p = sample_statistics(l.peak);
    md << "| " << l.mesh << " | " << l.level << " | " << fmt(l.h_avg, 4) << " | " << l.peak.size()
       << " | " << fmt(p.mean, 5) << (p.std_dev ? " ± " + fmt(*p.std_dev, 3) : "") << " | "
       << fmt(sample_statistics(l.dissipated).mean, 5) << " | "
       << fmt(sample_statistics(l.crack).mean, 4) << " | " << ks_text << " |\n";
  }
  summary["levels"] = out_levels;
  md << peak_extrapolation(levels, summary);
  double worst_closed_form = NAN;
  for (const FractureRecord& r : result.records)
    if (!std::isnan(r.closed_form_error))
      worst_closed_form = std::isnan(worst_closed_form)
                              ? r.closed_form_error
                              : std::max(worst_closed_form, r.closed_form_error);
  if (!std::isnan(worst_closed_form)) {
    summary["worst_closed_form_error"] = worst_closed_form;
    md << "\nLargest deviation from the tension bar's closed form over every converged point: "
       << fmt(worst_closed_form, 3) << " (load over sigma_c H t, stroke relative).\n";
  }
  double worst = 0.0;
  for (const FractureRecord& r : result.records) worst = std::max(worst, r.energy_balance_error);
  summary["worst_energy_balance_error"] = worst;
  md << "\nWorst energy balance error over every converged point of every run: " << fmt(worst, 3)
     << " of the external work.\n\nFiles: results.csv (one row per run), curves/<run>.csv "
        "(one row per converged point), cracks/<run>.csv (faces past the strength), "
        "vtu/<run>.pvd (deformed mesh, magnified, with interface states).\n";
  for (const FractureRecord& r : result.records) {
    if (!r.complete) md << "\n- " << r.run.id() << " is incomplete: " << r.failure << "\n";
    if (!r.ended.empty()) md << "\n- " << r.run.id() << " ended early: " << r.ended << "\n";
  }
  write_file_atomically(out / "summary.json", summary.dump(1) + "\n");
  write_file_atomically(out / "report.md", md.str());
}

}  // namespace

FractureStudyResult run_fracture_study(const FractureScene& scene, const fs::path& out, int threads,
                                       bool progress) {
  check_fracture_meshes(scene, ensemble_runs(scene.meshes));
  FractureStudyResult result = run_study_records<FractureRecord>(
      scene.meshes, out, threads, progress, fracture_fields(),
      [&](const EnsembleRunId& id) { return run_fracture(scene, id, out); },
      [](const FractureRecord& r) {
        return r.run.id() + ": peak " + fmt(r.peak_load, 5) + " N, " + std::to_string(r.points) +
               " points, " + fmt(r.seconds, 3) + " s" +
               (r.complete ? "" : " (incomplete: " + r.failure + ")") +
               (r.ended.empty() ? "" : " (ended: " + r.ended + ")");
      });
  if (Ensemble::writes_reports()) write_reports(scene, result, out);
  return result;
}

}  // namespace vorodg
