// The coordinator's cost per task (TaskPool): many trivial tasks (each returns one short
// results line at once), so the time per task is the pool's own: handing a task out, the
// message round trip under MPI, and recording its line. Run it alone for the local pool, or
// under `mpirun -n N` for the coordinator of an MPI job (every rank runs the same fixed
// iterations; rank 0 reports).
//   BM_TrivialTasks/N   N tasks per pool, one worker thread per rank
// Counters: seconds_per_task (median over the repetitions is the figure to quote).
#include <benchmark/benchmark.h>

#include <iostream>
#include <string>

#include "verification/harness/Ensemble.hpp"
#include "verification/harness/TaskPool.hpp"

namespace {

using namespace vorodg;

void BM_TrivialTasks(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  std::vector<Task> tasks(n);
  for (int i = 0; i < n; ++i) tasks[i] = {{i}, 1.0};
  std::size_t recorded = 0;
  for (auto _ : state) {
    run_tasks(
        tasks, 1,
        [](const Task& task) {
          return TaskOutput{{"{\"id\": " + std::to_string(task.runs.front()) + "}"}, {""}};
        },
        [&](const Task&, const TaskOutput& out) { recorded += out.lines.size(); });
  }
  state.counters["ranks"] = Ensemble::size();
  state.counters["seconds_per_task"] = benchmark::Counter(
      double(state.iterations()) * n, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  benchmark::DoNotOptimize(recorded);
}

// Fixed iterations: every rank of an MPI job must join the same number of pools.
BENCHMARK(BM_TrivialTasks)->Arg(10000)->Iterations(5)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  Ensemble::start(argc, argv);
  if (!Ensemble::coordinator()) std::cout.rdbuf(nullptr);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  Ensemble::stop();
  return 0;
}
