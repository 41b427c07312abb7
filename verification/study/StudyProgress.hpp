#pragma once
// The progress line of a study: runs done, time spent, and an estimate of the time left that
// weighs every run by its expected cost (its expected DOFs to a power), so a study whose fine
// levels come last is not promised to end early.
#include <atomic>
#include <cstddef>
#include <mutex>
#include <vector>

#include "core/util/Stopwatch.hpp"
#include "verification/model/RunRecord.hpp"
#include "verification/study/Scene.hpp"

namespace vorodg {

/// The expected cost of a run in arbitrary units, from the scene alone (no mesh is built):
/// its expected degrees of freedom to the power 1.1 (fitted on fig26: CG time
/// grows as DOFs^1.04, DG as DOFs^1.12).
double expected_cost(const Scene& scene, const StudyRun& run);

class StudyProgress {
 public:
  /// `costs` of every run of the study; `done[i]` says run i is already finished.
  StudyProgress(std::vector<double> costs, const std::vector<bool>& done, bool show);
  /// Run i has finished.
  void finished(std::size_t i);
  /// The estimate of the seconds left, from the cost done since the start.
  double seconds_left() const;

 private:
  void print(std::size_t done_runs) const;

  std::vector<double> costs_;
  double total_cost_ = 0.0, cost_done_before_ = 0.0, cost_done_now_ = 0.0;
  std::size_t runs_ = 0, runs_done_ = 0;
  bool show_, tty_;
  Stopwatch clock_;
  mutable std::mutex lock_;
};

}  // namespace vorodg
