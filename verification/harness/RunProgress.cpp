#include "verification/harness/RunProgress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>

#include "core/util/Format.hpp"

namespace vorodg {

RunProgress::RunProgress(std::vector<double> costs, const std::vector<bool>& done, bool show)
    : costs_(std::move(costs)), runs_(costs_.size()), show_(show), tty_(isatty(fileno(stderr))) {
  for (std::size_t i = 0; i < costs_.size(); ++i) {
    total_cost_ += costs_[i];
    if (done[i]) cost_done_before_ += costs_[i], ++runs_done_;
  }
}

double RunProgress::seconds_left() const {
  const double left = total_cost_ - cost_done_before_ - cost_done_now_;
  return cost_done_now_ > 0 ? clock_.seconds() / cost_done_now_ * left : 0.0;
}

void RunProgress::finished(std::size_t i) {
  std::lock_guard<std::mutex> guard(lock_);
  cost_done_now_ += costs_[i];
  ++runs_done_;
  if (show_) print(runs_done_);
}

void RunProgress::print(std::size_t now) const {
  std::ostringstream line;
  line << "runs " << now << "/" << runs_ << ", " << fmt(clock_.seconds(), 3) << " s elapsed, ~"
       << fmt(seconds_left(), 3) << " s left";
  if (tty_) {
    const double fraction = (cost_done_before_ + cost_done_now_) / std::max(total_cost_, 1e-300);
    const int width = 30, filled = static_cast<int>(width * fraction);
    std::cerr << "\r[" << std::string(filled, '#') << std::string(width - filled, '.') << "] "
              << line.str() << "   " << std::flush;
    if (now == runs_) std::cerr << "\n";
  } else if (now == runs_ || now % std::max<std::size_t>(runs_ / 10, 1) == 0) {
    std::cerr << line.str() << "\n";
  }
}

}  // namespace vorodg
