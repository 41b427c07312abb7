#include "verification/harness/EnsembleRun.hpp"

#include <set>
#include <utility>

#include "core/util/Errors.hpp"
#include "core/util/Random.hpp"
#include "verification/harness/Ensemble.hpp"

namespace vorodg {

std::vector<EnsembleRunId> ensemble_runs(const std::vector<SceneMesh>& meshes) {
  std::vector<EnsembleRunId> runs;
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const SceneMesh& mesh = meshes[m];
    // A run's id is its block's label, level and realization: two blocks with one label would
    // write, and resume, each other's runs.
    for (std::size_t o = 0; o < m; ++o)
      if (meshes[o].label == mesh.label)
        throw InputError("meshes[" + std::to_string(m) + "]: label '" + mesh.label +
                         "' is also meshes[" + std::to_string(o) +
                         "]'s: expected a label of its own (their runs would share ids)");
    for (int level = 0; level < static_cast<int>(mesh.sizes.size()); ++level)
      for (int r = 0; r < mesh.realizations_at(level); ++r)
        runs.push_back({static_cast<int>(m), level, r, mesh.label,
                        derive_seed(derive_seed(mesh.seed, level), r)});
  }
  return runs;
}

void check_each_level(const std::vector<EnsembleRunId>& runs,
                      const std::function<void(const EnsembleRunId&)>& build,
                      const std::string& where) {
  std::set<std::pair<int, int>> seen;
  for (const EnsembleRunId& run : runs)
    if (seen.insert({run.mesh, run.level}).second) try {
        build(run);
      } catch (const InputError& e) {  // say which mesh of the scene, at which level
        throw InputError(where + "meshes[" + std::to_string(run.mesh) + "] level " +
                         std::to_string(run.level) + ": " + e.what());
      }
}

std::vector<nlohmann::json> run_ensemble(
    const std::vector<SceneMesh>& meshes, const std::vector<EnsembleRunId>& runs,
    const std::filesystem::path& out, int threads, bool progress,
    const std::function<RunOutcome(const EnsembleRunId&)>& execute) {
  std::vector<std::string> ids;
  std::vector<double> costs;
  for (const EnsembleRunId& id : runs) {
    ids.push_back(id.id());
    costs.push_back(level_cost(meshes.at(id.mesh), id.level));
  }
  RunLoopOptions options{threads, progress, true};
  const auto done = run_resumable(RunPlan::one_per_run(ids, costs), out / "results.jsonl", options,
                                  [&](const std::vector<std::size_t>& block) {
                                    return std::vector<RunOutcome>{execute(runs[block.front()])};
                                  });
  std::vector<nlohmann::json> records;
  if (!Ensemble::writes_reports()) return records;  // the coordinator of a whole study
  for (const std::string& id : ids) records.push_back(done.at(id));
  return records;
}

}  // namespace vorodg
