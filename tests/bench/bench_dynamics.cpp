// Throughput of explicit dynamics on rcp meshes of the 4 x 1 domain, in cell-steps per second
// (items_per_second; per_core divides by the threads):
//   BM_InternalForce/N/threads   f = K u over all cells: the cell mat-vecs into pair slots, the
//                                fixed-order gather to nodes and the ordered energy sum
//   BM_CorotationalForce/N       the same force with turning frames (the column's kinematics)
//   BM_BulkViscosity/N           bulk viscosity's cell forces in the current configuration
//                                (the column's), their gather to nodes and the damping check
//   BM_Step/N/threads            one whole central-difference step (force, updates, bookkeeping)
//   BM_Lanczos/N                 the global critical-step estimate (iterations as a counter)
// Target: >= 2e6 cell-steps/s per core for the internal force at 1e5 cells.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "BenchMeshes.hpp"
#include "core/dofs/SplitDofMap.hpp"
#include "core/element/ElasticityIntegrator.hpp"
#include "core/element/ElementTable.hpp"
#include "core/util/Random.hpp"
#include "dynamics/BulkViscosity.hpp"
#include "dynamics/CentralDifference.hpp"
#include "dynamics/GlobalTimeStep.hpp"
#include "dynamics/InternalForce.hpp"
#include "dynamics/LumpedMass.hpp"
#include "dynamics/StableTimeStep.hpp"

namespace {

using namespace vorodg;

/// Everything for an rcp mesh of about n cells, built once per n (2 setup threads).
struct Model {
  PolygonMesh mesh;
  ElementTable table;
  LumpedMass mass;
  ElasticityIntegrator::CellMatrices matrices;
  StableTimeStep limit;
  explicit Model(const MeshSpec& spec)
      : mesh(generate_mesh(spec).mesh),
        table(mesh, bench::setup_options()),
        mass(table, 7800.0),
        matrices(
            ElasticityIntegrator(table, IsotropicElasticity(200e9, 0.3, PlaneModel::strain), false)
                .all_cell_matrices(2)),
        limit(mesh, matrices, mass, 2) {}
};

const Model& model(int n) {
  return bench::once_per_size<Model>(n);
}

Eigen::VectorXd random_vector(int size, double amplitude) {
  Random random(3);
  Eigen::VectorXd x(size);
  for (int i = 0; i < size; ++i) x[i] = random.uniform(-amplitude, amplitude);
  return x;
}

void report(benchmark::State& state, int cells, int threads) {
  state.SetItemsProcessed(state.iterations() * cells);
  state.counters["cells"] = cells;
  state.counters["per_core"] =
      benchmark::Counter(double(state.iterations()) * cells / threads, benchmark::Counter::kIsRate);
}

void BM_InternalForce(benchmark::State& state) {
  const Model& m = model(static_cast<int>(state.range(0)));
  const int threads = static_cast<int>(state.range(1));
  InternalForce force(m.mesh, m.matrices);
  const SplitDofMap dofs = SplitDofMap::continuous(m.mesh);
  const Eigen::VectorXd u = random_vector(dofs.num_dofs(), 1e-6);
  Eigen::VectorXd f(dofs.num_dofs());
  for (auto _ : state) benchmark::DoNotOptimize(force.compute(dofs, u, f, threads));
  report(state, m.mesh.num_cells(), threads);
}

void BM_CorotationalForce(benchmark::State& state) {
  const Model& m = model(static_cast<int>(state.range(0)));
  InternalForce force(m.mesh, m.matrices, /*corotational=*/true);
  const SplitDofMap dofs = SplitDofMap::continuous(m.mesh);
  const Eigen::VectorXd u = random_vector(dofs.num_dofs(), 1e-6);
  Eigen::VectorXd f(dofs.num_dofs());
  for (auto _ : state) benchmark::DoNotOptimize(force.compute(dofs, u, f, 1));
  report(state, m.mesh.num_cells(), 1);
}

void BM_BulkViscosity(benchmark::State& state) {
  const Model& m = model(static_cast<int>(state.range(0)));
  // The column's b1 and b2; a steel-like dilatational speed.
  BulkViscosity bulk(m.mesh, {0.06, 1.2}, 7800.0, std::vector<double>(m.mesh.num_cells(), 6000.0));
  bulk.set_current_configuration(true);
  const SplitDofMap dofs = SplitDofMap::continuous(m.mesh);
  const Eigen::VectorXd u = random_vector(dofs.num_dofs(), 1e-6);
  const Eigen::VectorXd v = random_vector(dofs.num_dofs(), 1e-3);
  Eigen::VectorXd f(dofs.num_dofs());
  for (auto _ : state) {
    bulk.compute(dofs, v, f, 1, &u);
    benchmark::DoNotOptimize(f.data());
  }
  report(state, m.mesh.num_cells(), 1);
}

void BM_Step(benchmark::State& state) {
  const Model& m = model(static_cast<int>(state.range(0)));
  const int threads = static_cast<int>(state.range(1));
  DynamicsOptions options;
  options.threads = threads;
  CentralDifference run(m.mesh, m.mass, InternalForce(m.mesh, m.matrices),
                        SplitDofMap::continuous(m.mesh), m.limit.step(), options);
  const int n = run.dofs().num_dofs();
  run.initialize(random_vector(n, 1e-6), Eigen::VectorXd::Zero(n));
  for (auto _ : state) benchmark::DoNotOptimize(run.step().elastic);
  report(state, m.mesh.num_cells(), threads);
}

void BM_Lanczos(benchmark::State& state) {
  const Model& m = model(static_cast<int>(state.range(0)));
  InternalForce force(m.mesh, m.matrices);
  const SplitDofMap dofs = SplitDofMap::continuous(m.mesh);
  const Eigen::VectorXd masses = m.mass.node_masses(dofs);
  int iterations = 0;
  double ratio = 0.0;
  for (auto _ : state) {
    const GlobalTimeStep global(force, dofs, masses, m.limit);
    iterations = global.iterations();
    ratio = m.limit.critical() / global.critical();
  }
  state.counters["lanczos_iterations"] = iterations;
  state.counters["cell_bound_over_lanczos"] = ratio;
}

BENCHMARK(BM_InternalForce)
    ->Args({100000, 1})
    ->Args({100000, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_CorotationalForce)->Arg(2500)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BulkViscosity)->Arg(2500)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Step)
    ->Args({100000, 1})
    ->Args({100000, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_Lanczos)->Arg(100000)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
