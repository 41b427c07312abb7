// meshes[].realizations_per_level: a count of random meshes per level instead of one for all
// (a statistical campaign runs many coarse realizations and few fine ones). The runs are those
// of each level's count, with the seeds a uniform count would give them (realization i of
// level l is the same mesh either way), and every bad form is refused in one line naming the key.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>

#include "core/util/Errors.hpp"
#include "verification/harness/EnsembleRun.hpp"
#include "verification/harness/MeshBlock.hpp"

namespace vorodg {
namespace {

const Rectangle kDomain(0.0, 0.0, 4.0, 1.0);

SceneMesh read(const std::string& text) {
  const nlohmann::json value = nlohmann::json::parse(text);  // the object reads it in place
  SceneObject m(value, "meshes[0]", "scene.json");
  return read_mesh(m, kDomain);
}

TEST(RealizationsPerLevel, EachLevelRunsItsOwnCountWithTheUniformSeeds) {
  const SceneMesh mesh = read(
      R"({"family": "rcp", "sizes": [0.5, 0.25, 0.125], "realizations_per_level": [3, 2, 1]})");
  EXPECT_EQ(mesh.realizations_at(0), 3);
  EXPECT_EQ(mesh.realizations_at(2), 1);
  const auto runs = ensemble_runs({mesh});
  ASSERT_EQ(runs.size(), 6u);
  const SceneMesh uniform =
      read(R"({"family": "rcp", "sizes": [0.5, 0.25, 0.125], "realizations": 3})");
  const auto all = ensemble_runs({uniform});
  for (const EnsembleRunId& run : runs) {
    EXPECT_LT(run.realization, mesh.realizations_at(run.level));
    const auto same = std::find_if(all.begin(), all.end(), [&](const EnsembleRunId& u) {
      return u.level == run.level && u.realization == run.realization;
    });
    ASSERT_NE(same, all.end());
    EXPECT_EQ(same->seed, run.seed) << run.id();
  }
}

TEST(RealizationsPerLevel, BadFormsAreRefusedNamingTheKey) {
  for (
      const char* text :
      {R"({"family": "rcp", "sizes": [0.5, 0.25], "realizations_per_level": [3]})",
       R"({"family": "rcp", "sizes": [0.5, 0.25], "realizations_per_level": [3, 1.5]})",
       R"({"family": "rcp", "sizes": [0.5, 0.25], "realizations_per_level": [3, 0]})",
       R"({"family": "rcp", "sizes": [0.5, 0.25], "realizations_per_level": [3, "two"]})",
       R"({"family": "rcp", "sizes": [0.5, 0.25], "realizations": 2, "realizations_per_level": [3, 1]})"}) {
    try {
      read(text);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("realizations_per_level"), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace vorodg
