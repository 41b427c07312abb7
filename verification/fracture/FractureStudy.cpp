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
#include "verification/report/Extrapolation.hpp"
#include "verification/report/KolmogorovSmirnov.hpp"
#include "verification/report/SampleStatistics.hpp"
#include "verification/study/Ensemble.hpp"
#include "verification/study/ResumableRuns.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace vorodg {
namespace {

json to_json(const FractureRecord& r) {
  json j = {{"id", r.run.id()},
            {"mesh", r.run.label},
            {"level", r.run.level},
            {"realization", r.run.realization},
            {"seed", r.run.seed},
            {"cells", r.cells},
            {"dofs", r.dofs},
            {"full_dg_dofs", r.full_dg_dofs},
            {"h_avg", r.h_avg},
            {"peak_load", r.peak_load},
            {"displacement_at_peak", r.displacement_at_peak},
            {"dissipated_energy", r.dissipated_energy},
            {"crack_length", r.crack_length},
            {"energy_balance_error", r.energy_balance_error},
            {"points", r.points},
            {"newton_iterations", r.newton_iterations},
            {"factorizations", r.factorizations},
            {"complete", r.complete},
            {"failure", r.failure},
            {"ended", r.ended},
            {"seconds", r.seconds}};
  if (!std::isnan(r.closed_form_error)) j["closed_form_error"] = r.closed_form_error;
  return j;
}

FractureRecord from_json(const json& j, const FractureRunId& id) {
  FractureRecord r;
  r.run = id;
  r.cells = j.at("cells"), r.dofs = j.at("dofs"), r.full_dg_dofs = j.at("full_dg_dofs");
  r.h_avg = j.at("h_avg"), r.peak_load = j.at("peak_load");
  r.displacement_at_peak = j.at("displacement_at_peak");
  r.dissipated_energy = j.at("dissipated_energy"), r.crack_length = j.at("crack_length");
  r.energy_balance_error = j.at("energy_balance_error");
  r.points = j.at("points"), r.newton_iterations = j.at("newton_iterations");
  r.factorizations = j.at("factorizations");
  r.complete = j.at("complete"), r.failure = j.at("failure"), r.seconds = j.at("seconds");
  r.ended = j.value("ended", "");
  if (j.contains("closed_form_error")) r.closed_form_error = j.at("closed_form_error");
  return r;
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
  std::ostringstream csv;
  csv << "id,mesh,level,realization,cells,dofs,full_dg_dofs,h_avg,peak_load,displacement_at_peak,"
         "dissipated_energy,crack_length,energy_balance_error,closed_form_error,complete,"
         "seconds\n";
  for (const FractureRecord& r : result.records)
    csv << r.run.id() << ',' << r.run.label << ',' << r.run.level << ',' << r.run.realization << ','
        << r.cells << ',' << r.dofs << ',' << r.full_dg_dofs << ',' << fmt(r.h_avg, 12) << ','
        << fmt(r.peak_load, 12) << ',' << fmt(r.displacement_at_peak, 12) << ','
        << fmt(r.dissipated_energy, 12) << ',' << fmt(r.crack_length, 12) << ','
        << fmt(r.energy_balance_error, 6) << ','
        << (std::isnan(r.closed_form_error) ? "" : fmt(r.closed_form_error, 6)) << ','
        << (r.complete ? 1 : 0) << ',' << fmt(r.seconds, 6) << '\n';
  write_file_atomically(out / "results.csv", csv.str());

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
  const std::vector<FractureRunId> runs = fracture_runs(scene);
  check_fracture_meshes(scene, runs);
  fs::create_directories(out);
  std::vector<std::string> ids;
  std::vector<double> costs;
  for (const FractureRunId& id : runs) {
    ids.push_back(id.id());
    costs.push_back(level_cost(scene.meshes.at(id.mesh), id.level));
  }
  const auto done =
      run_resumable(ids, costs, out / "results.jsonl", threads, progress, [&](std::size_t i) {
        FractureRecord r;
        try {
          r = run_fracture(scene, runs[i], out);
        } catch (const std::exception& e) {
          r.run = runs[i];
          r.failure = e.what();
        }
        return RunOutcome{to_json(r), r.run.id() + ": peak " + fmt(r.peak_load, 5) + " N, " +
                                          std::to_string(r.points) + " points, " +
                                          fmt(r.seconds, 3) + " s" +
                                          (r.complete ? "" : " (incomplete: " + r.failure + ")") +
                                          (r.ended.empty() ? "" : " (ended: " + r.ended + ")")};
      });
  FractureStudyResult result;
  if (!Ensemble::writes_reports()) return result;  // the coordinator of a whole study
  for (const FractureRunId& id : runs) {
    result.records.push_back(from_json(done.at(id.id()), id));
    if (!result.records.back().complete) ++result.incomplete;
  }
  write_reports(scene, result, out);
  return result;
}

}  // namespace vorodg
