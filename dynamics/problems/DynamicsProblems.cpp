// The registry of dynamics problems, in the order docs and messages list them. A problem is a
// DynamicsProblem in its own file of this folder, made by make_<name>(); adding one is its file
// and one line here.
#include "dynamics/problems/DynamicsProblem.hpp"

#define VORODG_DYNAMICS_PROBLEMS(PROBLEM) \
  PROBLEM(wave_bar)                       \
  PROBLEM(free_body)                      \
  PROBLEM(wall_impact)                    \
  PROBLEM(two_blocks)                     \
  PROBLEM(strip_expansion)                \
  PROBLEM(column_impact)                  \
  PROBLEM(projectile_impact)              \
  PROBLEM(three_point_bend)

namespace vorodg {

#define VORODG_DECLARE_PROBLEM(name) std::unique_ptr<DynamicsProblem> make_##name();
VORODG_DYNAMICS_PROBLEMS(VORODG_DECLARE_PROBLEM)

std::vector<std::unique_ptr<DynamicsProblem>> dynamics_problems() {
#define VORODG_MAKE_PROBLEM(name) problems.push_back(make_##name());
  std::vector<std::unique_ptr<DynamicsProblem>> problems;
  VORODG_DYNAMICS_PROBLEMS(VORODG_MAKE_PROBLEM)
  return problems;
}

}  // namespace vorodg
