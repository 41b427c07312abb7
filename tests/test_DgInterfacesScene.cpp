// `interfaces: dg` in a dynamics scene (docs/dynamics.md, "Interfaces coupled from the start"):
// every interior edge split from t = 0 and held by the interior-penalty coupling.
//   - the wave bar (steel strip, plane stress, free sides, rcp h = 12.5 mm): the pulse arrives at
//     the bar speed within 0.5 % (measured -0.25 %, as the continuous map's -0.23 %), the energy
//     balance closes to round-off, and the step is the coupled system's (smaller than the
//     continuous map's);
//   - refused, one line naming the key: with corotational kinematics (a fragmentation study's
//     default, or said), beside a varying material.
#include <gtest/gtest.h>

#include "core/util/Errors.hpp"
#include "dynamics/problems/DynamicsProbe.hpp"
#include "verification/harness/EnsembleRun.hpp"
#include "verification/kinds/dynamics/DynamicsRun.hpp"

namespace vorodg {
namespace {

std::string wave_bar(const std::string& extra) {
  return R"({"study": "dynamics", "problem": "wave-bar", "domain": [0, 0, 1, 0.05],
    "material": {"E": 2e11, "nu": 0.3, "density": 7800, "plane": "stress"},
    "pulse": {"amplitude": 1}, "outputs": {"vtu": false},
    "meshes": [{"family": "rcp", "sizes": [0.0125], "seed": 5}])" +
         (extra.empty() ? "" : ", " + extra) + "}";
}

struct Bar {
  double speed_error = 0.0, balance = 0.0, dt = 0.0;
};

Bar run_bar(const std::string& text) {
  const DynamicsScene scene = parse_dynamics_scene(text, "test scene");
  ExplicitSimulation model = dynamics_simulation(scene, ensemble_runs(scene.meshes).front());
  DynamicsProbe probe(scene, *scene.problem, model.bodies, *model.run, scene.output_every);
  for (long s = 0; s < model.steps; ++s) {
    model.run->step();
    probe.observe();
  }
  return {probe.measures().wave_speed_error, probe.measures().max_energy_balance_error, model.dt};
}

TEST(DgInterfacesScene, TheWaveBarKeepsItsSpeed) {
  const Bar continuous = run_bar(wave_bar("")), dg = run_bar(wave_bar(R"("interfaces": "dg")"));
  std::printf(
      "wave bar, rcp: speed error %+.3f%% continuous, %+.3f%% dg; dt %.3e and %.3e; "
      "balance %.1e\n",
      100 * continuous.speed_error, 100 * dg.speed_error, continuous.dt, dg.dt, dg.balance);
  EXPECT_LT(std::abs(dg.speed_error), 0.005);
  EXPECT_LT(dg.balance, 1e-12);
  EXPECT_LT(dg.dt, continuous.dt);
}

TEST(DgInterfacesScene, RefusedWhereItIsNotBuilt) {
  for (const std::string& bad :
       {std::string(R"({"study": "fragmentation", "problem": "strip-expansion",
           "interfaces": "dg", "meshes": [{"family": "rcp", "sizes": [1e-5]}]})"),
        wave_bar(R"("interfaces": "dg", "material": {"E": 2e11, "variation": 0.05})"),
        wave_bar(R"("interfaces": "dg", "kinematics": "corotational")"),
        wave_bar(R"("interfaces": "cohesive")")}) {
    try {
      parse_dynamics_scene(bad, "test scene");
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("interfaces"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace vorodg
