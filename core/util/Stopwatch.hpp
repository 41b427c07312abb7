#pragma once
// Wall-clock timing of pipeline stages; every run records seconds per stage.
#include <chrono>
#include <map>
#include <string>

namespace vorodg {

class Stopwatch {
 public:
  Stopwatch() : start_(Clock::now()) {}
  /// Seconds since construction or the last restart().
  double seconds() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }
  void restart() { start_ = Clock::now(); }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point start_;
};

/// Named stage timings, in the order a pipeline runs them (std::map keeps output stable).
using StageTimes = std::map<std::string, double>;

}  // namespace vorodg
