#pragma once
// The run pool of the ensemble studies (fracture, dynamics): every run whose id is not yet in
// results.jsonl is one task of the TaskPool (on `threads` worker threads of this process, or of
// every rank of an MPI job), and its record is appended there as one JSON line by the
// coordinator, flushed at once, so that a stopped study loses only the runs in flight and
// resumes where it stopped. A line cut short by the stop is ignored, and its run runs again.
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "verification/study/Scene.hpp"

namespace vorodg {

struct RunOutcome {
  nlohmann::json record;  // must hold "id"
  std::string progress;   // one line for the console
};

/// The expected cost of a run on level `level` of `mesh`, for the order runs start in: size^-3,
/// cells times steps of an explicit run (only the order matters).
double level_cost(const SceneMesh& mesh, int level);

/// The records of results.jsonl by id (complete lines only).
std::map<std::string, nlohmann::json> read_finished_runs(const std::filesystem::path& jsonl);

/// Runs `ids` not finished yet, largest expected cost (`costs`, one per id) first, `execute(i)`
/// running ids[i] (an exception is its caller's to turn into a failed record). Each worker has
/// one OpenMP thread, with dynamic teams (CHOLMOD asks for more whatever the setting); OpenBLAS
/// gets threads / workers threads. Returns every record by id, old and new, on the coordinator
/// (Ensemble); on the other ranks of an MPI job, what results.jsonl held at the start.
std::map<std::string, nlohmann::json> run_resumable(
    const std::vector<std::string>& ids, const std::vector<double>& costs,
    const std::filesystem::path& jsonl, int threads, bool progress,
    const std::function<RunOutcome(std::size_t)>& execute);

}  // namespace vorodg
