// The whole CG pipeline on rcp meshes: beam, plane stress, default element
// settings, two threads (the default of `vorodg solve` on this machine). Each benchmark iteration
// runs every stage; the counters give the seconds of each stage (mesh, element, pattern, cell
// matrices, assembly, cell means, analysis, factorization, solve, error), the factor's nonzeros
// and the peak memory, so the cost of everything else can be set against the factorization.
// Target at 1e6 cells: total at most 2x the factorization, peak memory at most 8 GB.
//
// The second argument is the solver: 0 cholmod, 1 amg-cg (its tolerance tied to the mesh), for
// the crossover of the two (docs/solvers.md). amg-cg adds the counters
// `amg_setup`, `iterations` and `relative_residual`. Peak memory is the process's so far: run
// one case per process (--benchmark_filter) to read it per case.
//
// The third argument is 1 when the run measures its errors (every study run does) and 0 for
// `vorodg solve --no-errors`, which skips the error integration and the weight functions'
// rebuild after the factorization: the pipeline a user pays for a solution alone.
#include <benchmark/benchmark.h>

#include <cmath>

#include "core/meshgen/MeshFamily.hpp"
#include "core/util/PeakMemory.hpp"
#include "core/util/Stopwatch.hpp"
#include "verification/solve/SolveRun.hpp"

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
  settings.element.threads = 2;
  settings.solver.kind = state.range(1) ? LinearSolverKind::amg_cg : LinearSolverKind::cholmod;
  settings.errors = state.range(2) != 0;
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
    state.counters["factor_nonzeros"] = static_cast<double>(r.factor_nonzeros);
    state.counters["iterations"] = r.amg.iterations;
    state.counters["relative_residual"] = r.amg.relative_residual;
    if (r.errors_measured) state.counters["l2_error"] = r.l2_error;
  }
  for (const auto& [stage, s] : total) state.counters[stage] = s / state.iterations();
  state.counters["cells"] = n_cells;
  state.counters["peak_memory_mb"] = peak_memory_mb();  // of the process so far
  state.SetItemsProcessed(state.iterations() * n_cells);
}

}  // namespace

BENCHMARK(BM_CgPipeline)
    ->ArgNames({"cells", "amg", "errors"})
    ->ArgsProduct({{1000, 10000, 30000, 100000, 300000}, {0, 1}, {1}})
    ->Args({100000, 0, 0})
    ->Unit(benchmark::kSecond)
    ->UseRealTime();
BENCHMARK(BM_CgPipeline)
    ->ArgNames({"cells", "amg", "errors"})
    ->ArgsProduct({{1000000}, {0, 1}, {1}})
    ->Args({1000000, 0, 0})
    ->Iterations(1)
    ->Repetitions(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

BENCHMARK_MAIN();
