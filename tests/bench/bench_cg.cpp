// The whole CG pipeline on rcp meshes (issue 4): beam, plane stress, default element settings,
// one thread. Each benchmark iteration runs every stage; the counters give the median seconds of
// each stage (mesh, element, cell matrices, assembly, analysis, factorization, solve, error) so
// the cost of everything else can be set against the factorization. Target at 1e6 cells:
// everything except factorization + solve costs less than the factorization.
#include <benchmark/benchmark.h>

#include <cmath>

#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Stopwatch.hpp"
#include "verification/SolveRun.hpp"

namespace {

using namespace vorodg;

void BM_CgPipeline(benchmark::State& state) {
  const double cells = static_cast<double>(state.range(0));
  MeshSpec spec;
  spec.family = MeshFamily::rcp;
  spec.domain = Rectangle(0.0, -0.5, 4.0, 0.5);
  spec.size = std::sqrt(0.7 * spec.domain.area() / cells);
  spec.seed = 5;
  SolveSettings settings;
  settings.problem = "beam";
  StageTimes total;
  int n_cells = 0;
  for (auto _ : state) {
    Stopwatch clock;
    const GeneratedMesh mesh = generate_mesh(spec);
    const double mesh_seconds = clock.seconds();
    const SolveResult r = run_solve(mesh.mesh, settings);
    benchmark::DoNotOptimize(r.l2_error);
    total["mesh"] += mesh_seconds;
    for (const auto& [stage, s] : r.seconds) total[stage] += s;
    n_cells = mesh.mesh.num_cells();
    state.counters["dofs"] = r.dofs;
  }
  for (const auto& [stage, s] : total) state.counters[stage] = s / state.iterations();
  state.counters["cells"] = n_cells;
  state.SetItemsProcessed(state.iterations() * n_cells);
}

}  // namespace

BENCHMARK(BM_CgPipeline)->Arg(10000)->Arg(100000)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(BM_CgPipeline)->Arg(1000000)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

BENCHMARK_MAIN();
