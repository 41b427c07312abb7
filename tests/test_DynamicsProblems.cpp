// The dynamics problems as classes (dynamics/problems/):
//   - every problem of the registry reads from a scene that names it, with its defaults: the body's
//     domain, velocity and spin, gravity, and a run length (an end time or a step count);
//   - a key that only another problem reads is refused with one line naming the key and the
//     problem at hand, for every pair of problems;
//   - a problem that needs crack insertion is refused in a dynamics study;
//   - the key table's per-problem defaults are the problems' own, grouped ("else" for the
//     largest group of two or more).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "core/schema/SceneKeyReader.hpp"
#include "core/util/Errors.hpp"
#include "verification/kinds/dynamics/DynamicsKeys.hpp"
#include "verification/kinds/dynamics/DynamicsScene.hpp"
#include "verification/solve/SettingsSchema.hpp"

namespace vorodg {
namespace {

std::string scene(const DynamicsProblem& p, const std::string& extra = "") {
  return std::string(R"({"study": ")") + (p.needs_fragmentation() ? "fragmentation" : "dynamics") +
         R"(", "problem": ")" + p.name() +
         R"(", "material": {"E": 2e11, "nu": 0.3, "density": 7800},
    "outputs": {"vtu": false}, "meshes": [{"family": "quad", "sizes": [)" +
         exact_text(p.default_domain().scale() / 10) + "]}]" + (extra.empty() ? "" : ", " + extra) +
         "}";
}

/// A value of the right shape for each problem's own key.
std::string value_of(const std::string& key) {
  if (key == "sides") return R"("rollers")";
  if (key == "strain_rate" || key == "obliquity") return "10";
  return "{}";
}

TEST(DynamicsProblems, EachReadsWithItsDefaults) {
  for (const std::unique_ptr<DynamicsProblem>& p : dynamics_problems()) {
    const DynamicsScene s = parse_dynamics_scene(scene(*p), "test");
    ASSERT_TRUE(s.problem) << p->name();
    EXPECT_EQ(s.problem->name(), p->name());
    EXPECT_EQ(s.bodies[0].domain.lo(), p->default_domain().lo()) << p->name();
    EXPECT_EQ(s.bodies[0].domain.hi(), p->default_domain().hi()) << p->name();
    EXPECT_EQ(s.bodies[0].velocity, p->default_velocity()) << p->name();
    EXPECT_EQ(s.bodies[0].angular_velocity, p->default_angular_velocity()) << p->name();
    EXPECT_EQ(s.gravity, p->default_gravity()) << p->name();
    EXPECT_TRUE((s.end > 0.0) != (s.steps > 0))
        << p->name() << ": end " << s.end << ", steps " << s.steps;
    EXPECT_EQ(static_cast<bool>(s.wall), p->hits_wall()) << p->name();
    EXPECT_EQ(external_momentum(s, *s.problem), p->hits_wall() || p->prescribes_velocity() ||
                                                    p->default_gravity() != Eigen::Vector2d::Zero())
        << p->name();
  }
}

TEST(DynamicsProblems, AnotherProblemsKeyIsRefusedNamingTheProblem) {
  int checked = 0;
  for (const std::unique_ptr<DynamicsProblem>& p : dynamics_problems())
    for (const std::unique_ptr<DynamicsProblem>& other : dynamics_problems()) {
      if (other->name() == p->name()) continue;
      for (const std::string& key : other->own_keys()) {
        const std::vector<std::string> own = p->own_keys();
        if (std::find(own.begin(), own.end(), key) != own.end()) continue;
        try {
          parse_dynamics_scene(scene(*p, "\"" + key + "\": " + value_of(key)), "test");
          ADD_FAILURE() << p->name() << " took " << key;
        } catch (const InputError& e) {
          const std::string what = e.what();
          EXPECT_NE(what.find(key), std::string::npos) << what;
          EXPECT_NE(what.find("not used by problem " + p->name()), std::string::npos) << what;
          ++checked;
        }
      }
    }
  EXPECT_GE(checked, 30);  // 8 problems, 9 own keys: at least 6 x 6 refusals
}

TEST(DynamicsProblems, CrackInsertionProblemsNeedAFragmentationStudy) {
  for (const std::unique_ptr<DynamicsProblem>& p : dynamics_problems()) {
    if (!p->needs_fragmentation()) continue;
    std::string text = scene(*p);
    text.replace(text.find("fragmentation"), 13, "dynamics");
    EXPECT_THROW(parse_dynamics_scene(text, "test"), InputError) << p->name();
  }
}

TEST(DynamicsProblems, KeyTableDefaultsComeFromTheProblems) {
  const std::string velocity = dynamics_key("initial_velocity").fallback;
  EXPECT_EQ(velocity,
            "per problem: free-body [1, 0.5], wall-impact and two-blocks [1, 0], column-impact "
            "[0, -7.6], else [0, 0]");
  EXPECT_EQ(dynamics_key("gravity").fallback, "per problem: column-impact [0, -9.81], else [0, 0]");
  const std::string domain = dynamics_key("domain").fallback;
  for (const std::unique_ptr<DynamicsProblem>& p : dynamics_problems()) {
    EXPECT_NE(domain.find(p->name() + " " + rect_text(p->default_domain())), std::string::npos)
        << domain;
    EXPECT_NE(dynamics_key("problem").range.find(p->name()), std::string::npos);
  }
}

}  // namespace
}  // namespace vorodg
