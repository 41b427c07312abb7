#pragma once
// The check of a trade-off study's recommendation: the configuration recommended for the
// smallest target error runs once more, at the mesh size its error-size line predicts for that
// error, on `verification_realizations` fresh meshes (the level after the finest, in the seed
// stream), in the subfolder `verification/` of the study with its own results.jsonl (resumable
// like the study). Its median time and mean error are set beside the prediction.
//
// The check is a scene of its own, made from the study's records alone, so that a rerun or a
// report-only merge finds the same runs again. Wall times of one machine are only comparable on
// that machine: a study split over MPI ranks or shards runs no check (the report says so).
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "verification/kinds/tradeoff/TradeoffAnalysis.hpp"
#include "verification/solve/RunRecord.hpp"
#include "verification/static/StudyRunner.hpp"

namespace vorodg {

inline constexpr const char* kTradeoffCheckFolder = "verification";

struct TradeoffCheck {
  TradeoffTarget target;  // what was predicted
  int runs = 0, failed = 0;
  std::optional<double> seconds, seconds_min, seconds_max;  // median and range
  std::optional<double> l2_error;                           // mean
  std::optional<double> dofs;                               // mean
  /// measured / predicted seconds - 1 (with a median)
  std::optional<double> time_deviation() const;
};

/// The scene of the check, or none with the reason in `why_not`: verify is off, no configuration
/// has a cost line, the predicted size needs more than 10 times the cells of the configuration's
/// finest level, or the meshes are read from files (no size to ask for).
std::optional<Scene> tradeoff_check_scene(const Scene& scene, const TradeoffAnalysis& analysis,
                                          std::string& why_not);

/// Runs the check (what `out`/verification does not hold yet) after the study's runs, in this
/// process only: nothing in an MPI job of several ranks or in a shard.
void run_tradeoff_check(const Scene& scene, const std::vector<RunRecord>& records,
                        const StudyOptions& options);

/// The outcome of the check `check` (made by tradeoff_check_scene for `target`) from the
/// records in `out`/verification, or none if it has not run.
std::optional<TradeoffCheck> read_tradeoff_check(const Scene& check, const TradeoffTarget& target,
                                                 const std::filesystem::path& out);

}  // namespace vorodg
