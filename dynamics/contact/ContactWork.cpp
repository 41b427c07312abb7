#include "dynamics/contact/ContactWork.hpp"

#include <string>

#include "core/io/StateArchive.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {

void ContactWork::add(std::span<const Point> f, std::span<const int> support,
                      std::span<const Point> velocity, double dt) {
  if (f.size() != velocity.size())
    throw InputError("contact work: " + std::to_string(f.size()) + " forces and " +
                     std::to_string(velocity.size()) +
                     " velocities: expected one of each per pair");
  for (int p : support)
    if (p < 0 || p >= static_cast<int>(f.size()))
      throw InputError("contact work: pair " + std::to_string(p) + " out of range [0, " +
                       std::to_string(f.size()) + ")");
  if (started_) {
    double step = 0.0;  // in a fixed order: the same sum on every run
    for (const auto& [p, old] : last_) step += 0.5 * dt * old.dot(velocity[p]);
    for (int p : support) step += 0.5 * dt * f[p].dot(velocity[p]);
    work_ += step;
  }
  last_.clear();
  for (int p : support) last_.emplace_back(p, f[p]);
  started_ = true;
}

void ContactWork::archive(StateArchive& a) {
  a.each("work.last", last_, [](StateArchive& item, std::pair<int, Point>& force) {
    item.value("work.pair", force.first);
    item.value("work.force", force.second);
  });
  a.value("work.total", work_);
  a.value("work.started", started_);
}

void SegmentedWork::archive(StateArchive& a) {
  current_.archive(a);
  a.value("work.booked", booked_);
}

}  // namespace vorodg
