#pragma once
// The runs of an ensemble study (fracture, dynamics, fragmentation): one per (mesh block, level,
// realization) of the scene's `meshes`, with the realization's seed derived as every study
// derives it, and the resumable, sharded loop that runs those not yet in results.jsonl. A kind
// supplies what one run does and how its record reads back; the loop, the ids, the seeds, the
// order of costs and the failure of one run are the harness's.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "verification/harness/MeshBlock.hpp"
#include "verification/harness/ResumableRuns.hpp"

namespace vorodg {

struct EnsembleRunId {
  int mesh = 0, level = 0, realization = 0;  // indices into the scene's meshes
  std::string label;                         // the mesh block's label
  std::uint64_t seed = 0;
  /// "<label>-L<level>-R<realization>": the run's name in records, files and messages.
  std::string id() const {
    return label + "-L" + std::to_string(level) + "-R" + std::to_string(realization);
  }
};

/// Every run of the mesh blocks: each block, level and realization, in that order.
std::vector<EnsembleRunId> ensemble_runs(const std::vector<SceneMesh>& meshes);

/// Calls `build` on the first realization of every (mesh block, level), so that a scene whose
/// meshes cannot carry its problem is refused before anything runs or is written. An InputError
/// is rethrown as "<where>meshes[m] level l: <what>".
void check_each_level(const std::vector<EnsembleRunId>& runs,
                      const std::function<void(const EnsembleRunId&)>& build,
                      const std::string& where);

/// Runs what results.jsonl in `out` does not hold yet, largest levels first; `execute` runs one
/// and turns any failure into its record. Returns the records of every run (old and new) in the
/// order of `runs` on the process that writes the reports, and nothing elsewhere.
std::vector<nlohmann::json> run_ensemble(
    const std::vector<SceneMesh>& meshes, const std::vector<EnsembleRunId>& runs,
    const std::filesystem::path& out, int threads, bool progress,
    const std::function<RunOutcome(const EnsembleRunId&)>& execute);

}  // namespace vorodg
