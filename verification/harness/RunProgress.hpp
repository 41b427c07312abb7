#pragma once
// The progress line of a study: runs done, time spent, and an estimate of the time left that
// weighs every run by its expected cost (what the kind says a run costs, in any unit), so a study
// whose fine levels come last is not promised to end early. Printed on stderr: a bar on a
// terminal, every tenth of the runs otherwise.
#include <cstddef>
#include <mutex>
#include <vector>

#include "core/util/Stopwatch.hpp"

namespace vorodg {

class RunProgress {
 public:
  /// `costs` of every run of the study; `done[i]` says run i is already finished.
  RunProgress(std::vector<double> costs, const std::vector<bool>& done, bool show);
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
