// DG iteration cost against the factorization: the beam on rcp meshes with dg-nitsche
// and dg-al (k_p = 1e3 E); counters give the analysis and factorization seconds of a + eps P and
// the seconds of one iteration (back-solve + interface-load update). Target at 1e5 cells: one
// iteration <= 10% of the factorization.
#include <benchmark/benchmark.h>

#include <cmath>

#include "core/meshgen/MeshFamily.hpp"
#include "verification/SolveRun.hpp"

namespace {

using namespace vorodg;

void BM_DgIteration(benchmark::State& state) {
  MeshSpec spec;
  spec.family = MeshFamily::rcp;
  spec.domain = Rectangle(0.0, -0.5, 4.0, 0.5);
  spec.size = std::sqrt(0.7 * spec.domain.area() / static_cast<double>(state.range(0)));
  spec.seed = 5;
  const GeneratedMesh mesh = generate_mesh(spec);
  SolveSettings settings;
  settings.formulation = state.range(1) == 0 ? "dg-nitsche" : "dg-al";
  settings.dg.kp = 1e3;
  settings.energy_error = false;
  SolveResult r;
  for (auto _ : state) {
    r = run_solve(mesh.mesh, settings);
    benchmark::DoNotOptimize(r.l2_error);
  }
  state.counters["cells"] = mesh.mesh.num_cells();
  state.counters["dofs"] = r.dofs;
  state.counters["analysis"] = r.seconds["analysis"];
  state.counters["factorization"] = r.seconds["factorization"];
  state.counters["iteration"] = r.dg->seconds_per_iteration;
  state.counters["iterations"] = r.dg->iterations;
  state.counters["iteration_over_factorization"] =
      r.dg->seconds_per_iteration / r.seconds["factorization"];
}

}  // namespace

BENCHMARK(BM_DgIteration)
    ->Args({1000, 0})
    ->Args({10000, 0})
    ->Args({100000, 0})
    ->Args({100000, 1})
    ->Iterations(1)
    ->Repetitions(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

BENCHMARK_MAIN();
