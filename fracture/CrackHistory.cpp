#include "fracture/CrackHistory.hpp"

#include <algorithm>
#include <string>
#include <unordered_map>

#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

/// Per edge, the step at which the run cracked it; a second event on one edge is refused.
std::unordered_map<int, long> crack_steps(const std::vector<CrackEvent>& events,
                                          const char* which) {
  std::unordered_map<int, long> steps;
  for (const CrackEvent& e : events)
    if (!steps.emplace(e.edge, e.step).second)
      throw InputError(std::string("crack history of run ") + which + ": edge " +
                       std::to_string(e.edge) + " cracks twice");
  return steps;
}

}  // namespace

std::vector<DistanceAtStep> hamming_history(const std::vector<CrackEvent>& a,
                                            const std::vector<CrackEvent>& b) {
  const std::unordered_map<int, long> in_a = crack_steps(a, "a"), in_b = crack_steps(b, "b");
  // An edge cracked in one run at step s and in the other at step t (or never) differs over
  // [min(s, t), max(s, t)): +1 at the first, -1 at the second.
  std::vector<std::pair<long, int>> changes;
  auto add = [&](const std::unordered_map<int, long>& mine,
                 const std::unordered_map<int, long>& other) {
    for (const auto& [edge, step] : mine) {
      const auto it = other.find(edge);
      if (it == other.end()) {
        changes.push_back({step, +1});
      } else if (step < it->second) {
        changes.push_back({step, +1});
        changes.push_back({it->second, -1});
      }
    }
  };
  add(in_a, in_b);
  add(in_b, in_a);
  std::vector<long> event_steps;
  for (const auto& e : a) event_steps.push_back(e.step);
  for (const auto& e : b) event_steps.push_back(e.step);
  std::sort(event_steps.begin(), event_steps.end());
  event_steps.erase(std::unique(event_steps.begin(), event_steps.end()), event_steps.end());
  std::sort(changes.begin(), changes.end());
  std::vector<DistanceAtStep> history;
  int distance = 0;
  std::size_t next = 0;
  for (long step : event_steps) {
    for (; next < changes.size() && changes[next].first <= step; ++next)
      distance += changes[next].second;
    history.push_back({step, distance});
  }
  return history;
}

}  // namespace vorodg
