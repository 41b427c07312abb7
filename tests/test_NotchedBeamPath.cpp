// The notched three-point-bend beam end to end, on the four shipped cases at their coarsest
// level (pre-inserted, restricted, contiguous and arbitrary cracking): every run follows its path
// to an end (its load vanished, or the test ended once the load was nearly gone), the energy
// balance holds at every converged point within 1e-3 of the work, and the dissipation stays below
// the fracture energy of the whole ligament.
// No closed form exists for the beam; these are the invariants a path follower must keep.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "verification/kinds/fracture/FractureRun.hpp"
#include "verification/kinds/fracture/FractureScene.hpp"

namespace vorodg {
namespace {

namespace fs = std::filesystem;

const fs::path kScenes = fs::path(VORODG_TEST_DATA).parent_path().parent_path() / "data" / "scenes";

/// The shipped scene with its meshes cut to the first level.
FractureScene coarsest_level(const std::string& name) {
  std::ifstream in(kScenes / (name + ".json"));
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json j = nlohmann::json::parse(text.str());
  for (auto& mesh : j["meshes"]) mesh["sizes"] = nlohmann::json::array({mesh["sizes"][0]});
  return parse_fracture_scene(j.dump(), name);
}

class NotchedBeam : public ::testing::TestWithParam<std::string> {};

TEST_P(NotchedBeam, FollowsItsPathWithTheEnergyBalanced) {
  const FractureScene scene = coarsest_level(GetParam());
  const fs::path out = fs::temp_directory_path() / ("vorodg_notched_" + GetParam());
  fs::remove_all(out);
  const double ligament = scene.geometry.domain.height() - scene.geometry.notch_depth;
  const double whole_ligament = scene.law.fracture_energy * ligament * scene.thickness;
  for (const EnsembleRunId& id : ensemble_runs(scene.meshes)) {
    const FractureRecord r = run_fracture(scene, id, out);
    ASSERT_TRUE(r.complete) << id.id() << ": " << r.failure;
    EXPECT_FALSE(r.ended.empty()) << id.id() << " should end where its load vanishes";
    EXPECT_LE(r.energy_balance_error, 1e-3) << id.id();
    EXPECT_GT(r.dissipated_energy, 0.0) << id.id();
    EXPECT_LE(r.dissipated_energy, whole_ligament * (1.0 + 1e-9)) << id.id();
  }
  fs::remove_all(out);
}

INSTANTIATE_TEST_SUITE_P(Cases, NotchedBeam,
                         ::testing::Values("tpb-case1", "tpb-case2", "tpb-case3", "tpb-case4"),
                         [](const auto& info) {
                           std::string s = info.param;
                           for (char& c : s)
                             if (c == '-') c = '_';
                           return s;
                         });

}  // namespace
}  // namespace vorodg
