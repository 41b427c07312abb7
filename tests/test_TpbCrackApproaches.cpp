// The notched beam's two crack approaches (problem three-point-bend, interfaces insertion | dg;
// docs/dynamics.md, "The dynamic three-point bend"), on tpb-dynamic-quick's mesh (rcp d = 0.04):
//   - with dg in restricted mode only the crack line's edges are coupled: the map splits the line
//     and the notch, and the notch's interfaces carry nothing;
//   - in pre-inserted mode the two approaches are the same run (no edge is coupled: the line is
//     cohesive from t = 0), step for step;
//   - a restricted dg run to 1.5 mm activates edges of the line, keeps the integrator's balance
//     to 1e-10 of the input and the law's to 1e-3, and books the work at activation.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "verification/kinds/dynamics/DynamicsRun.hpp"

namespace vorodg {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

DynamicsScene quick(const json& changes) {
  const fs::path path =
      fs::path(VORODG_TEST_DATA).parent_path().parent_path() / "data/scenes/tpb-dynamic-quick.json";
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  json j = json::parse(text.str());
  j.merge_patch(changes);
  return parse_dynamics_scene(j.dump(), "tpb-dynamic-quick");
}

TEST(TpbCrackApproaches, OnlyTheCrackLineIsCoupled) {
  const DynamicsScene scene = quick({{"cracking", {{"mode", "restricted"}}}, {"interfaces", "dg"}});
  const ExplicitSimulation model = dynamics_simulation(scene, ensemble_runs(scene.meshes).front());
  ASSERT_TRUE(model.coupling.has_value());
  const PolygonMesh& mesh = model.mesh();
  int line = 0, notch = 0, active = 0;
  for (int i = 0; i < model.coupling->num_interfaces(); ++i) {
    const MeshEdge& e = mesh.edge(model.coupling->space().interfaces()[i].edge);
    const Point a = mesh.vertex(e.v0), b = mesh.vertex(e.v1);
    ASSERT_NEAR(a.x(), 1.0, 1e-12);  // every interface is on the vertical line x = 1
    ASSERT_NEAR(b.x(), 1.0, 1e-12);
    const bool in_notch = std::max(a.y(), b.y()) <= 0.1 + 1e-12;
    (in_notch ? notch : line) += 1;
    if (model.coupling->active(i)) {
      ++active;
      EXPECT_FALSE(in_notch);
    }
  }
  EXPECT_GT(line, 1);
  EXPECT_GT(notch, 0);
  EXPECT_EQ(active, line);
}

TEST(TpbCrackApproaches, PreInsertedIsTheSameRunWithEitherApproach) {
  const DynamicsScene insertion = quick({{"rate", {{"max_displacement", 2e-4}}}}),
                      dg = quick({{"rate", {{"max_displacement", 2e-4}}}, {"interfaces", "dg"}});
  ExplicitSimulation a = dynamics_simulation(insertion, ensemble_runs(insertion.meshes).front());
  ExplicitSimulation b = dynamics_simulation(dg, ensemble_runs(dg.meshes).front());
  ASSERT_EQ(a.dt, b.dt);
  for (int k = 0; k < 2000; ++k) a.cracks->step(), b.cracks->step();
  EXPECT_EQ(a.run->displacement(), b.run->displacement());
}

TEST(TpbCrackApproaches, ARestrictedDgRunActivatesTheLineBalanced) {
  const DynamicsScene scene = quick({{"cracking", {{"mode", "restricted"}}},
                                     {"interfaces", "dg"},
                                     {"criterion", {{"friction", 0.75}}},
                                     {"cohesive", {{"face_friction", 0}}}});
  const EnsembleRunId id = ensemble_runs(scene.meshes).front();
  const fs::path out = fs::temp_directory_path() / ("vorodg_tpb_dg_" + std::to_string(getpid()));
  fs::remove_all(out);
  const DynamicsRecord r = run_dynamics(scene, id, out);
  const DynamicsMeasures& m = r.measures;
  std::printf(
      "restricted dg: %g interfaces activated, peak %.1f N, balance %.1e, law balance "
      "%.1e, work at activation %.1e of the input\n",
      m.activated_interfaces, m.peak_load, m.max_energy_balance_error, m.law_balance_error,
      m.activation_work);
  ASSERT_TRUE(r.complete) << r.failure;
  EXPECT_GE(m.activated_interfaces, 1.0);
  EXPECT_LT(m.max_energy_balance_error, 1e-10);
  EXPECT_LT(m.law_balance_error, 1e-3);
  EXPECT_TRUE(std::isfinite(m.activation_work));
  fs::remove_all(out);
}

}  // namespace
}  // namespace vorodg
