#include "verification/kinds/tradeoff/TradeoffVerification.hpp"

#include <algorithm>
#include <iostream>

#include "core/util/Format.hpp"
#include "core/util/Random.hpp"
#include "verification/harness/Ensemble.hpp"
#include "verification/harness/ResumableRuns.hpp"
#include "verification/report/SampleStatistics.hpp"

namespace vorodg {
namespace {

/// A check may ask for at most this many times the cells of the configuration's finest level
/// (cells go as size^-2): a target far beyond the study would make the check the longest part of
/// it, and test an extrapolation the report already calls one. Judged on the size line, which
/// the errors alone fix, so that timing noise cannot decide whether the check runs.
constexpr double kMaxCheckCells = 10.0;

}  // namespace

std::optional<double> TradeoffCheck::time_deviation() const {
  if (!seconds) return std::nullopt;
  return *seconds / target.seconds - 1.0;
}

std::optional<Scene> tradeoff_check_scene(const Scene& scene, const TradeoffAnalysis& analysis,
                                          std::string& why_not) {
  if (!scene.tradeoff.verify) {
    why_not = "switched off (tradeoff.verify false)";
    return std::nullopt;
  }
  if (analysis.targets.empty() || !analysis.targets.back().config) {
    why_not = "no admitted configuration has an error-cost line";
    return std::nullopt;
  }
  const TradeoffTarget& target = analysis.targets.back();  // the smallest error
  const double finest = target.config->levels.back().size;
  const double cells = (finest / target.size) * (finest / target.size);
  if (cells > kMaxCheckCells) {
    why_not = "the predicted size " + fmt(target.size, 4) + " needs about " + fmt(cells, 3) +
              " times the cells of the finest level (size " + fmt(finest, 4) + "), more than " +
              fmt(kMaxCheckCells) + ": give tradeoff.targets within reach, or verify false";
    return std::nullopt;
  }
  const GroupSummary& g = *target.config->group;
  const auto mesh = std::find_if(scene.meshes.begin(), scene.meshes.end(),
                                 [&](const SceneMesh& m) { return m.label == g.mesh; });
  const auto form = std::find_if(scene.formulations.begin(), scene.formulations.end(),
                                 [&](const SceneFormulation& f) { return f.label == g.label; });
  if (mesh->family == MeshFamily::file) {
    why_not = "the meshes are files: there is no mesh of the predicted size to make";
    return std::nullopt;
  }
  Scene check = scene;
  check.name = scene.name + " verification";
  check.study = "convergence";
  SceneMesh m = *mesh;
  // The level after the finest in the seed stream; the size in the label, so that a changed
  // prediction is a new run rather than an old record read back.
  m.seed = derive_seed(m.seed, m.sizes.size());
  m.sizes = {target.size};
  m.realizations = scene.tradeoff.verification_realizations;
  m.label = g.mesh + " size " + fmt(target.size, 6);
  SceneFormulation f = *form;
  if (g.kp) f.kp = {*g.kp};
  check.meshes = {m};
  check.formulations = {f};
  check.problems = {g.problem};
  check.nu = {g.nu};
  return check;
}

void run_tradeoff_check(const Scene& scene, const std::vector<RunRecord>& records,
                        const StudyOptions& options) {
  if (Ensemble::size() > 1 || Ensemble::shard().count > 1 || Ensemble::report_only()) return;
  const StudySummary summary = summarize_study(scene, records, published_reference(scene));
  const TradeoffAnalysis analysis = analyse_tradeoff(scene, summary, records);
  std::string why_not;
  const std::optional<Scene> check = tradeoff_check_scene(scene, analysis, why_not);
  if (!check) return;
  const TradeoffTarget& target = analysis.targets.back();
  std::cout << "\n== check: " << target.config->variant << " at size " << fmt(target.size, 4)
            << " (predicted " << fmt(target.seconds, 3) << " s for L2 error "
            << fmt(target.error, 3) << ")\n";
  StudyOptions sub = options;
  sub.out = options.out / kTradeoffCheckFolder;
  run_study(*check, sub);
}

std::optional<TradeoffCheck> read_tradeoff_check(const Scene& check, const TradeoffTarget& target,
                                                 const std::filesystem::path& out) {
  const auto lines = read_finished_runs(out / kTradeoffCheckFolder / "results.jsonl");
  TradeoffCheck c;
  c.target = target;
  std::vector<double> seconds, errors, dofs;
  for (const StudyRun& run : expand_runs(check)) {
    const auto line = lines.find(run.id);
    if (line == lines.end()) continue;
    const RunRecord r = record_from_json(run, line->second);
    ++c.runs;
    if (!r.ok()) {
      ++c.failed;
      continue;
    }
    seconds.push_back(r.metrics->total_seconds());
    errors.push_back(r.metrics->l2_error);
    dofs.push_back(r.metrics->dofs);
  }
  if (c.runs == 0) return std::nullopt;
  if (seconds.empty()) return c;
  const SampleStatistics time = sample_statistics(seconds);
  c.seconds = time.median, c.seconds_min = time.min, c.seconds_max = time.max;
  c.l2_error = sample_statistics(errors).mean;
  c.dofs = sample_statistics(dofs).mean;
  return c;
}

}  // namespace vorodg
