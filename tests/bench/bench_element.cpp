// Throughput of the RK element layer, in cells per second (items_per_second), on rcp
// meshes of the 4 x 1 beam domain:
//   BM_WeightFunctions/N/refinement/degree   the vertex-patch Poisson solves alone
//   BM_ElementTable/N/refinement/degree      weights + quadrature + shape functions + correction
//   BM_ElementTableThreads/N/threads         the default setting on 1 and 2 threads
//   BM_CellStiffness/N                       the shared cell-stiffness kernel over all cells
//   BM_CongruentCells/N/family               finding the congruent cells alone (0 rcp, 1 quad)
//   BM_QuadElementTable/N/reuse              the default table on the quad grid of the beam,
//                                            every cell computed (0) or one per class (1)
//   BM_ErrorNorms/N                          the L2 and energy errors of the beam's nodal
//                                            interpolant (the error stage of a solve)
//   BM_ElementFamily/N/family                the element table of each element family
//                                            (0 rk, 1 wachspress, 2 mean-value, 3 vem) on the raw
//                                            Voronoi mesh (regularization 0: convex cells)
// Target at the default setting: >= 100k cells/s on one core. One thread unless stated.
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <memory>

#include "BenchMeshes.hpp"
#include "core/element/CongruentCells.hpp"
#include "core/element/ElasticityIntegrator.hpp"
#include "core/element/ElementTable.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/problem/ErrorNorms.hpp"
#include "core/problem/TimoshenkoBeam.hpp"

namespace {

using namespace vorodg;

/// rcp meshes of about n cells, generated once per n.
const PolygonMesh& rcp_mesh(int n) {
  static std::map<int, std::unique_ptr<PolygonMesh>> cache;
  auto& slot = cache[n];
  if (!slot) {
    slot = std::make_unique<PolygonMesh>(generate_mesh(bench::rcp_spec(n)).mesh);
  }
  return *slot;
}

/// The same, unregularized: every cell convex, as Wachspress coordinates need.
const PolygonMesh& raw_rcp_mesh(int n) {
  static std::map<int, std::unique_ptr<PolygonMesh>> cache;
  auto& slot = cache[n];
  if (!slot) {
    MeshSpec spec = bench::rcp_spec(n);
    spec.regularization = 0.0;
    slot = std::make_unique<PolygonMesh>(generate_mesh(spec).mesh);
  }
  return *slot;
}

/// The beam's quad grid (4 x 1) with about n cells, generated once per n.
const PolygonMesh& quad_mesh(int n) {
  static std::map<int, std::unique_ptr<PolygonMesh>> cache;
  auto& slot = cache[n];
  if (!slot) {
    MeshSpec spec;
    spec.family = MeshFamily::quad;
    spec.domain = Rectangle(0.0, -0.5, 4.0, 0.5);
    spec.size = 2.0 / std::sqrt(static_cast<double>(n));
    slot = std::make_unique<PolygonMesh>(generate_mesh(spec).mesh);
  }
  return *slot;
}

ElementOptions options_for(int refinement, int degree, int threads) {
  ElementOptions o;
  o.weights.refinement = refinement;
  o.weights.degree = degree;
  o.threads = threads;
  return o;
}

void BM_WeightFunctions(benchmark::State& state) {
  const PolygonMesh& mesh = rcp_mesh(static_cast<int>(state.range(0)));
  const auto o = options_for(static_cast<int>(state.range(1)), static_cast<int>(state.range(2)), 1);
  for (auto _ : state) {
    WeightFunctions weights(mesh, o.weights, 1);
    benchmark::DoNotOptimize(weights.values(0, 0).data());
  }
  state.SetItemsProcessed(state.iterations() * mesh.num_cells());
  state.counters["cells"] = mesh.num_cells();
}

void BM_ElementTable(benchmark::State& state) {
  const PolygonMesh& mesh = rcp_mesh(static_cast<int>(state.range(0)));
  const auto o = options_for(static_cast<int>(state.range(1)), static_cast<int>(state.range(2)), 1);
  for (auto _ : state) {
    ElementTable table(mesh, o);
    benchmark::DoNotOptimize(table.shape(0, 0, 0));
  }
  state.SetItemsProcessed(state.iterations() * mesh.num_cells());
  state.counters["cells"] = mesh.num_cells();
}

void BM_ElementTableThreads(benchmark::State& state) {
  const PolygonMesh& mesh = rcp_mesh(static_cast<int>(state.range(0)));
  const ElementOptions defaults;
  auto o = options_for(defaults.weights.refinement, defaults.weights.degree,
                       static_cast<int>(state.range(1)));
  for (auto _ : state) {
    ElementTable table(mesh, o);
    benchmark::DoNotOptimize(table.shape(0, 0, 0));
  }
  state.SetItemsProcessed(state.iterations() * mesh.num_cells());
}

void BM_ElementFamily(benchmark::State& state) {
  const PolygonMesh& mesh = raw_rcp_mesh(static_cast<int>(state.range(0)));
  ElementOptions o;
  constexpr ElementFamily kFamilies[] = {ElementFamily::rk, ElementFamily::wachspress,
                                         ElementFamily::mean_value, ElementFamily::vem};
  o.family = kFamilies[state.range(1)];
  for (auto _ : state) {
    ElementTable table(mesh, o);
    benchmark::DoNotOptimize(table.shape(0, 0, 0));
  }
  state.SetItemsProcessed(state.iterations() * mesh.num_cells());
}

void BM_CongruentCells(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const PolygonMesh& mesh = state.range(1) == 0 ? rcp_mesh(n) : quad_mesh(n);
  for (auto _ : state) {
    const CongruentCells classes(mesh);
    benchmark::DoNotOptimize(classes.num_classes());
  }
  state.SetItemsProcessed(state.iterations() * mesh.num_cells());
}

void BM_QuadElementTable(benchmark::State& state) {
  const PolygonMesh& mesh = quad_mesh(static_cast<int>(state.range(0)));
  ElementOptions o;
  o.reuse_congruent = state.range(1) != 0;
  for (auto _ : state) {
    ElementTable table(mesh, o);
    benchmark::DoNotOptimize(table.shape(0, 0, 0));
  }
  state.SetItemsProcessed(state.iterations() * mesh.num_cells());
}

void BM_CellStiffness(benchmark::State& state) {
  const PolygonMesh& mesh = rcp_mesh(static_cast<int>(state.range(0)));
  const ElementTable table(mesh, ElementOptions{});
  const ElasticityIntegrator integrator(table, IsotropicElasticity(1.0, 0.3, PlaneModel::stress),
                                        state.range(1) != 0);
  Eigen::MatrixXd K;
  for (auto _ : state) {
    for (int c = 0; c < mesh.num_cells(); ++c) {
      integrator.cell_matrix(c, K);
      benchmark::DoNotOptimize(K.data());
    }
  }
  state.SetItemsProcessed(state.iterations() * mesh.num_cells());
}

void BM_ErrorNorms(benchmark::State& state) {
  const PolygonMesh& mesh = rcp_mesh(static_cast<int>(state.range(0)));
  const ElementTable table(mesh, ElementOptions{});
  const IsotropicElasticity material(1.0, 0.3, PlaneModel::stress);
  const TimoshenkoBeam beam(material, 4.0, 1.0, 1.0);
  auto cell_dofs = [&](int c) {  // the exact solution at the cell's vertices
    const auto loop = mesh.cell_vertices(c);
    Eigen::VectorXd u(2 * loop.size());
    for (std::size_t k = 0; k < loop.size(); ++k)
      u.segment<2>(2 * k) = beam.displacement(mesh.vertex(loop[k]));
    return u;
  };
  for (auto _ : state) benchmark::DoNotOptimize(compute_errors(table, beam, cell_dofs).l2_error);
  state.SetItemsProcessed(state.iterations() * mesh.num_cells());
}

void weight_settings(benchmark::internal::Benchmark* b) {
  for (int n : {10000, 100000})
    for (auto [refinement, degree] : {std::pair{0, 1}, {1, 1}, {2, 1}, {0, 2}, {1, 2}})
      b->Args({n, refinement, degree});
}

}  // namespace

BENCHMARK(BM_WeightFunctions)->Apply(weight_settings)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ElementTable)->Apply(weight_settings)->Unit(benchmark::kMillisecond)->UseRealTime();
// The default setting (P2, refinement 0) over the whole range, 1e3 to 1e6 cells.
BENCHMARK(BM_WeightFunctions)->Args({1000, 0, 2})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ElementTable)->Args({1000, 0, 2})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_WeightFunctions)
    ->Args({1000000, 0, 2})
    ->Iterations(1)
    ->Repetitions(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_ElementTable)
    ->Args({1000000, 0, 2})
    ->Iterations(1)
    ->Repetitions(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_ElementTableThreads)
    ->Args({100000, 1})
    ->Args({100000, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_ElementFamily)
    ->ArgNames({"cells", "family"})
    ->ArgsProduct({{100000}, {0, 1, 2, 3}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_CongruentCells)
    ->ArgNames({"cells", "family"})
    ->ArgsProduct({{100000}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_QuadElementTable)
    ->ArgNames({"cells", "reuse"})
    ->ArgsProduct({{65536, 262144}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_ErrorNorms)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CellStiffness)->Args({100000, 0})->Args({100000, 1})->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
