// Time per load step of the quasi-static fracture path: Petersson's beam of the shipped
// tpb-case1 scene (pre-inserted) and tpb-case2 (restricted) at about 1e4 and 1e5 cells, over the
// first three of its 100 steps (to a crack mouth opening of 30 um: the notch-tip faces start to
// soften; the steps through the peak cost several times more, see docs/performance-fracture.md).
// Counters: cells, DOFs, steps, seconds per step of the path alone (setup excluded), setup
// seconds, factorizations and Newton iterations per step.
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>

#include "verification/kinds/fracture/FractureRun.hpp"
#include "verification/kinds/fracture/FractureScene.hpp"

namespace {

using namespace vorodg;
namespace fs = std::filesystem;

constexpr double kSteps = 3;  // of the scene's 100 to max_cmod

void BM_FractureStep(benchmark::State& state) {
  const char* name = state.range(1) == 0 ? "tpb-case1.json" : "tpb-case2.json";
  FractureScene scene = read_fracture_scene(fs::path(VORODG_SCENES) / name);
  // rcp cells ~ 0.7 area / d^2 (the sampler's packing), for the requested count.
  scene.meshes.resize(1);
  scene.meshes[0].sizes = {
      std::sqrt(0.7 * scene.geometry.domain.area() / static_cast<double>(state.range(0)))};
  scene.meshes[0].realizations = 1;
  scene.loading.max_cmod *= kSteps / scene.loading.steps;
  scene.loading.steps = static_cast<int>(kSteps);
  scene.loading.tail_steps = 0;
  scene.vtu_every = 0;
  EnsembleRunId id;
  id.label = "bench";
  id.seed = 5;
  const fs::path out = fs::temp_directory_path() / "vorodg_bench_fracture";
  FractureRecord r;
  for (auto _ : state) {
    r = run_fracture(scene, id, out);
    benchmark::DoNotOptimize(r.peak_load);
  }
  fs::remove_all(out);
  const double steps = std::max(r.points - 1, 1);
  state.counters["cells"] = r.cells;
  state.counters["dofs"] = r.dofs;
  state.counters["steps"] = steps;
  state.counters["seconds_per_step"] = r.path_seconds / steps;
  state.counters["setup_seconds"] = r.seconds - r.path_seconds;
  state.counters["factorizations_per_step"] = r.factorizations / steps;
  state.counters["iterations_per_step"] = r.newton_iterations / steps;
  state.counters["complete"] = r.complete;
}

}  // namespace

// range(0): cells; range(1): 0 pre-inserted (case 1), 1 restricted (case 2).
BENCHMARK(BM_FractureStep)
    ->ArgsProduct({{10000, 100000}, {0, 1}})
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

BENCHMARK_MAIN();
