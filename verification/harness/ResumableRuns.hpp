#pragma once
// The run loop of every study kind. A study is a list of runs, each with a stable id and an
// expected cost, grouped into blocks: the runs that share one unit of work (the static kinds'
// mesh, made once for every problem, material and formulation on it; one run of the ensemble
// kinds). Every block with a run whose id is not yet in results.jsonl is one task of the
// TaskPool (on `threads` worker threads of this process, or of every rank of an MPI job); each
// record is appended there as one JSON line by the coordinator, flushed at once, so that a
// stopped study loses only the blocks in flight and resumes where it stopped. A line cut short
// by the stop is ignored, and its run runs again.
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "verification/harness/MeshBlock.hpp"

namespace vorodg {

struct RunOutcome {
  nlohmann::json record;  // must hold "id"
  std::string progress;   // one line for the console (none if empty)
};

/// What the loop runs. A block's place among every block of the plan, finished or not, is what
/// `--shard K/N` splits by, so every shard sees the same plan.
struct RunPlan {
  std::vector<std::string> ids;
  std::vector<double> costs;                     // per run, in any unit: only the order matters
  std::vector<std::vector<std::size_t>> blocks;  // every run in exactly one block

  /// One block per run.
  static RunPlan one_per_run(std::vector<std::string> ids, std::vector<double> costs);
};

struct RunLoopOptions {
  int threads = 2;
  bool progress = true;
  /// OpenBLAS threads: 1 per run always (results independent of --threads), or the threads the
  /// workers leave spare (a single fine run left gets them all).
  bool spare_threads_to_blas = false;
};

/// Executes the runs of one block still to do: their outcomes, in the order given.
using BlockExecutor = std::function<std::vector<RunOutcome>(const std::vector<std::size_t>&)>;
/// Whether a finished line of run i is one the kind reads (one that is not runs again).
using ReadableLine = std::function<bool(std::size_t, const nlohmann::json&)>;

/// The expected cost of a run on level `level` of `mesh`, for the order runs start in: size^-3,
/// cells times steps of an explicit run (only the order matters).
double level_cost(const SceneMesh& mesh, int level);

/// The records of results.jsonl by id (complete lines only; of two lines of one id, the last).
std::map<std::string, nlohmann::json> read_finished_runs(const std::filesystem::path& jsonl);

/// Runs, block by block, the runs not finished yet (a block's finished runs are not run again),
/// largest expected cost first; makes the folder of `jsonl` first (InputError if it cannot). An
/// exception out of `execute` ends the study: a kind turns the failure of a run into its record.
/// Each worker has one OpenMP thread, with dynamic teams (CHOLMOD asks for more whatever the
/// setting). Returns every record by id, old and new, on the coordinator (Ensemble); on the other
/// ranks of an MPI job, what results.jsonl held at the start.
std::map<std::string, nlohmann::json> run_resumable(const RunPlan& plan,
                                                    const std::filesystem::path& jsonl,
                                                    const RunLoopOptions& options,
                                                    const BlockExecutor& execute,
                                                    const ReadableLine& readable = {});

}  // namespace vorodg
