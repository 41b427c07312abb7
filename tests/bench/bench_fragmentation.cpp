// The cost of cracking in explicit dynamics, against a plain step, on rcp meshes of the 4 x 1
// domain (docs/fragmentation.md "Throughput"):
//   BM_PlainStep/N            one central-difference step, no cracks (the reference)
//   BM_InsertionCheck/N       CrackInsertion::failing_edges: every cell's mean stress and every
//                             edge's Mohr-Coulomb utilization (nothing fails)
//   BM_TurningInsertionCheck/N the same under turning frames (the column's kinematics), reading
//                             the local displacements the corotational force has just computed
//   BM_Remap/N                the connectivity rebuilt after cracks form: SplitDofMap from the
//                             uncracked edges, CentralDifference::remap (masses, binding, forces)
//                             from the continuous map to one split at one edge in twenty
//   BM_CrackingStep/N         DynamicFracture::step on a plate stretched in both directions until
//                             it fragments: step, check, and a remap whenever cracks form
//                             (counters: cracked edges, remaps per step, and the shares of
//                             the check and of the rebuild in its wall time)
// Everything on one thread; items_per_second counts cell-steps (or cell-checks, cell-remaps).
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "BenchMeshes.hpp"
#include "core/dofs/SplitDofMap.hpp"
#include "core/element/ElasticityIntegrator.hpp"
#include "core/element/ElementTable.hpp"
#include "core/util/Random.hpp"
#include "dynamics/CentralDifference.hpp"
#include "dynamics/DynamicFracture.hpp"
#include "dynamics/InternalForce.hpp"
#include "dynamics/LumpedMass.hpp"
#include "dynamics/StableTimeStep.hpp"

namespace {

using namespace vorodg;

constexpr double kE = 30e9, kDensity = 2400.0, kStrength = 3e6,
                 kToughness = 100.0;  // concrete-like

/// An rcp mesh of about n cells with its element data, built once per n.
struct Model {
  PolygonMesh mesh;
  ElementTable table;
  LumpedMass mass;
  ElasticityIntegrator integrator;
  ElasticityIntegrator::CellMatrices matrices;
  StableTimeStep limit;
  CohesiveLaw law;
  MohrCoulomb criterion{MohrCoulombParameters{kStrength, 0.0, kStrength}};
  std::vector<char> every_edge;
  double dt;
  explicit Model(const MeshSpec& spec)
      : mesh(generate_mesh(spec).mesh),
        table(mesh, bench::setup_options()),
        mass(table, kDensity),
        integrator(table, IsotropicElasticity(kE, 0.2, PlaneModel::strain), false),
        matrices(integrator.all_cell_matrices(2)),
        limit(mesh, matrices, mass, 2),
        law(CohesiveParameters{kStrength, kToughness, 1.0, "linear", 10.0 * kE / mesh.h_avg()}),
        every_edge(mesh.num_edges(), 1),
        dt(CohesiveForces::stable_step(limit, mesh, mass, law, every_edge, 0.9)) {}
};

const Model& model(int n) {
  return bench::once_per_size<Model>(n);
}

std::unique_ptr<CentralDifference> integrator(const Model& m) {
  return std::make_unique<CentralDifference>(m.mesh, m.mass, InternalForce(m.mesh, m.matrices),
                                             SplitDofMap::continuous(m.mesh), m.dt);
}

/// Stretching in both directions about the centre, at `rate` (1/s).
Eigen::VectorXd expansion(const CentralDifference& run, double rate) {
  Eigen::VectorXd v(run.dofs().num_dofs());
  for (int i = 0; i < run.dofs().num_nodes(); ++i)
    v.segment<2>(2 * i) = rate * (run.node_position(i) - Point(2.0, 0.5));
  return v;
}

void report(benchmark::State& state, int cells) {
  state.SetItemsProcessed(state.iterations() * cells);
  state.counters["cells"] = cells;
}

void BM_PlainStep(benchmark::State& state) {
  const Model& m = model(static_cast<int>(state.range(0)));
  auto run = integrator(m);
  run->initialize(Eigen::VectorXd::Zero(run->dofs().num_dofs()), expansion(*run, 1.0));
  for (auto _ : state) benchmark::DoNotOptimize(run->step().elastic);
  report(state, m.mesh.num_cells());
}

void BM_InsertionCheck(benchmark::State& state) {
  const Model& m = model(static_cast<int>(state.range(0)));
  auto run = integrator(m);
  run->initialize(Eigen::VectorXd::Zero(run->dofs().num_dofs()), expansion(*run, 1.0));
  for (int s = 0; s < 10; ++s) run->step();  // a small, nonzero strain: nothing fails
  const CrackInsertion insertion(m.mesh, m.integrator, m.criterion, m.every_edge);
  const std::vector<char> none(m.mesh.num_edges(), 0);
  for (auto _ : state)
    benchmark::DoNotOptimize(insertion.failing_edges(run->dofs(), run->displacement(), none, 1));
  report(state, m.mesh.num_cells());
}

void BM_TurningInsertionCheck(benchmark::State& state) {
  const Model& m = model(static_cast<int>(state.range(0)));
  auto run = integrator(m);
  run->initialize(Eigen::VectorXd::Zero(run->dofs().num_dofs()), expansion(*run, 1.0));
  for (int s = 0; s < 10; ++s) run->step();  // a small, nonzero strain: nothing fails
  InternalForce force(m.mesh, m.matrices, /*corotational=*/true);
  Eigen::VectorXd f;
  force.compute(run->dofs(), run->displacement(), f, 1);
  CrackInsertion insertion(m.mesh, m.integrator, m.criterion, m.every_edge);
  insertion.turn_with(force.frames());
  const std::vector<char> none(m.mesh.num_edges(), 0);
  for (auto _ : state)
    benchmark::DoNotOptimize(insertion.failing_edges(run->dofs(), run->displacement(), none, 1,
                                                     force.local_displacements()));
  report(state, m.mesh.num_cells());
}

void BM_Remap(benchmark::State& state) {
  const Model& m = model(static_cast<int>(state.range(0)));
  auto run = integrator(m);
  run->initialize(Eigen::VectorXd::Zero(run->dofs().num_dofs()), expansion(*run, 1.0));
  // One edge in twenty cracked, chosen with a fixed seed: the map splits at their junctions.
  std::vector<char> connected(m.mesh.num_edges(), 1);
  Random random(5);
  for (char& c : connected) c = random.uniform(0.0, 1.0) < 0.05 ? 0 : 1;
  for (auto _ : state) {
    state.PauseTiming();  // back to the continuous map: a merge, which fracture never does
    run->remap(SplitDofMap::continuous(m.mesh));
    state.ResumeTiming();
    run->remap(SplitDofMap(m.mesh, connected));
  }
  report(state, m.mesh.num_cells());
}

void BM_CrackingStep(benchmark::State& state) {
  const Model& m = model(static_cast<int>(state.range(0)));
  auto run = integrator(m);
  CohesiveForces cohesive(m.mesh, m.law);
  const CrackInsertion insertion(m.mesh, m.integrator, m.criterion, m.every_edge);
  DynamicFracture fracture(m.mesh, *run, cohesive, insertion);
  // Fast enough that the strength is reached in a few hundred steps.
  const double rate = kStrength / (kE * 200.0 * m.dt);
  run->initialize(Eigen::VectorXd::Zero(run->dofs().num_dofs()), expansion(*run, rate));
  for (int s = 0; s < 150; ++s) fracture.step(1);  // up to just before the first cracks
  const DynamicFracture::Times t0 = fracture.times();
  const double all0 = t0.integrator + t0.check + t0.rebuild;
  long steps = 0, remaps = 0;
  for (auto _ : state) {
    remaps += fracture.step(1) > 0;
    ++steps;
  }
  report(state, m.mesh.num_cells());
  state.counters["cracked_edges"] = static_cast<double>(cohesive.edges().size());
  // The shares of the timed steps' wall time (the steps before the loop excluded).
  const DynamicFracture::Times t = fracture.times();
  const double all = t.integrator + t.check + t.rebuild;
  state.counters["check_share"] = (t.check - t0.check) / (all - all0);
  state.counters["rebuild_share"] = (t.rebuild - t0.rebuild) / (all - all0);
  state.counters["remaps_per_step"] = double(remaps) / double(std::max(steps, 1L));
}

// 640, 2500 and 10000 cells: the sizes of the column-impact meshes at h = 4, 2 and 1, the
// reference of a fragmentation step's cost (docs/performance-fracture.md).
BENCHMARK(BM_PlainStep)
    ->Arg(640)
    ->Arg(2500)
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_InsertionCheck)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_TurningInsertionCheck)->Arg(2500)->Arg(10000)->UseRealTime();
BENCHMARK(BM_Remap)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CrackingStep)
    ->Arg(10000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(300);

}  // namespace

BENCHMARK_MAIN();
