#include "verification/study/StudyProgress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <numbers>
#include <sstream>
#include <string>

#include "core/util/Format.hpp"

namespace vorodg {
namespace {

/// Cells per unit area times size^2 of each family: saturated random sequential packing covers
/// about 0.547 of the area with disks of diameter d (rcp: one cell per seed; tri: about two
/// triangles per seed); a hexagon of spacing h has area (sqrt(3)/2) h^2; a square h^2.
double cells_per_size_squared(MeshFamily family) {
  switch (family) {
    case MeshFamily::rcp: return 0.547 * 4 / std::numbers::pi;
    case MeshFamily::tri: return 2 * 0.547 * 4 / std::numbers::pi;
    case MeshFamily::hex:
    case MeshFamily::perturbed_hex: return 2 / std::sqrt(3.0);
    default: return 1.0;
  }
}

}  // namespace

double expected_cost(const Scene& scene, const StudyRun& run) {
  const double cells =
      scene.domain.area() / (run.size * run.size) * cells_per_size_squared(run.family);
  // CG: about two vertices per cell, two DOFs each; DG: a copy of every vertex of every cell
  // (about six), which also makes its factor denser.
  const double dofs = run.kp ? 12 * cells : 4 * cells;
  return std::pow(dofs, 1.1);
}

StudyProgress::StudyProgress(std::vector<double> costs, const std::vector<bool>& done, bool show)
    : costs_(std::move(costs)), runs_(costs_.size()), show_(show), tty_(isatty(fileno(stderr))) {
  for (std::size_t i = 0; i < costs_.size(); ++i) {
    total_cost_ += costs_[i];
    if (done[i]) cost_done_before_ += costs_[i], ++runs_done_;
  }
}

double StudyProgress::seconds_left() const {
  const double left = total_cost_ - cost_done_before_ - cost_done_now_;
  return cost_done_now_ > 0 ? clock_.seconds() / cost_done_now_ * left : 0.0;
}

void StudyProgress::finished(std::size_t i) {
  std::lock_guard<std::mutex> guard(lock_);
  cost_done_now_ += costs_[i];
  ++runs_done_;
  if (show_) print(runs_done_);
}

void StudyProgress::print(std::size_t now) const {
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
