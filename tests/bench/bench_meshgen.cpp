// Throughput of the mesh generation pipeline, in cells per second (items_per_second), for
// N = 1e3 .. 1e6 cells on the 4 x 1 beam domain:
//   BM_PoissonDiskSampling  seeds (maximal Poisson-disk sampling)
//   BM_VoronoiTessellation  seeds -> clipped Voronoi mesh
//   BM_Regularization       short-edge collapse on the raw Voronoi mesh
//   BM_RcpGeneration        the whole rcp family through generate_mesh (the headline number;
//                           target >= 300k cells/s at 1e6 cells); BM_RcpGenerationTwoThreads
//                           the same with the seeding on two threads (the same meshes)
//   BM_MeshTopology         PolygonMesh construction (edges, vertex-cell map, boundary tags)
//   BM_HexGeneration        the hex family through generate_mesh
// The argument is the target number of cells; the counters report the cells actually made.
// Medians of repetitions are what we quote: see run_benchmarks.sh.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "core/geometry/Rectangle.hpp"
#include "core/mesh/PolygonMesh.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/meshgen/MeshRegularizer.hpp"
#include "core/meshgen/PoissonDiskSampler.hpp"
#include "core/meshgen/VoronoiTessellator.hpp"

namespace {

using namespace vorodg;

constexpr std::uint64_t kSeed = 20240607;

const Rectangle& bench_domain() {
  static const Rectangle domain{0.0, 0.0, 4.0, 1.0};
  return domain;
}

/// Minimum seed distance that gives about n cells: a saturated packing has N ~ 0.7 area / d^2
/// (covered fraction N pi d^2 / 4 / area ~ 0.547).
double spacing_for_cells(double n) {
  return std::sqrt(0.7 * bench_domain().area() / n);
}

/// Hexagon spacing (width across flats) for about n cells: a hexagon of that width has area
/// (sqrt(3)/2) s^2.
double hex_spacing_for_cells(double n) {
  return std::sqrt(bench_domain().area() / (n * std::sqrt(3.0) / 2.0));
}

/// The options of `sample_poisson_disk(domain, {.min_distance = d, .seed = seed})`, spelt out
/// member by member (a designated initializer trips -Wmissing-field-initializers).
PoissonDiskOptions sampling_options(double d, std::uint64_t seed) {
  PoissonDiskOptions options;
  options.min_distance = d;
  options.seed = seed;
  return options;
}

/// Inputs shared by several benchmarks, built once per N outside the timed loops.
struct RcpInputs {
  double d = 0.0;
  std::vector<Point> seeds;
  PolygonMesh raw;          // raw Voronoi mesh
  PolygonMesh regularized;  // the rcp mesh (for the topology benchmark)
};

const RcpInputs& rcp_inputs(std::int64_t n) {
  static std::map<std::int64_t, std::unique_ptr<RcpInputs>> cache;
  auto& slot = cache[n];
  if (!slot) {
    auto in = std::make_unique<RcpInputs>();
    in->d = spacing_for_cells(static_cast<double>(n));
    in->seeds = sample_poisson_disk(bench_domain(), sampling_options(in->d, kSeed)).points;
    in->raw = voronoi_mesh(bench_domain(), in->seeds, in->d);
    in->regularized = regularize_mesh(in->raw, 0.1 * in->d).mesh;
    slot = std::move(in);
  }
  return *slot;
}

void set_cells(benchmark::State& state, std::int64_t cells) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * cells);
  state.counters["cells"] = static_cast<double>(cells);
}

void BM_PoissonDiskSampling(benchmark::State& state) {
  const double d = spacing_for_cells(static_cast<double>(state.range(0)));
  std::int64_t points = 0;
  double darts = 0.0, passes = 0.0;
  std::uint64_t seed = kSeed;
  for (auto _ : state) {
    auto result = sample_poisson_disk(bench_domain(), sampling_options(d, seed++));
    points = static_cast<std::int64_t>(result.points.size());
    darts = static_cast<double>(result.darts_thrown);
    passes = result.refinement_passes;
    benchmark::DoNotOptimize(result.points.data());
  }
  set_cells(state, points);
  state.counters["darts_per_seed"] = darts / static_cast<double>(points);
  state.counters["passes"] = passes;
  state.counters["covered_fraction"] =
      covered_fraction(static_cast<std::size_t>(points), d, bench_domain().area());
}

void BM_VoronoiTessellation(benchmark::State& state) {
  const RcpInputs& in = rcp_inputs(state.range(0));
  std::int64_t cells = 0;
  for (auto _ : state) {
    PolygonMesh mesh = voronoi_mesh(bench_domain(), in.seeds, in.d);
    cells = mesh.num_cells();
    benchmark::DoNotOptimize(mesh.vertices().data());
  }
  set_cells(state, cells);
}

void BM_Regularization(benchmark::State& state) {
  const RcpInputs& in = rcp_inputs(state.range(0));
  std::int64_t cells = 0;
  int collapsed = 0;
  for (auto _ : state) {
    RegularizationResult result = regularize_mesh(in.raw, 0.1 * in.d);
    cells = result.mesh.num_cells();
    collapsed = result.collapsed_edges;
    benchmark::DoNotOptimize(result.mesh.vertices().data());
  }
  set_cells(state, cells);
  state.counters["collapsed_edges"] = collapsed;
}

void rcp_generation(benchmark::State& state, int threads) {
  MeshSpec spec;
  spec.threads = threads;
  spec.family = MeshFamily::rcp;
  spec.domain = bench_domain();
  spec.size = spacing_for_cells(static_cast<double>(state.range(0)));
  spec.regularization = 0.1;
  spec.seed = kSeed;
  std::int64_t cells = 0;
  for (auto _ : state) {
    GeneratedMesh generated = generate_mesh(spec);
    cells = generated.mesh.num_cells();
    benchmark::DoNotOptimize(generated.mesh.vertices().data());
    ++spec.seed;
  }
  set_cells(state, cells);
}

void BM_RcpGeneration(benchmark::State& state) {
  rcp_generation(state, 1);
}

void BM_RcpGenerationTwoThreads(benchmark::State& state) {
  rcp_generation(state, 2);
}

void BM_MeshTopology(benchmark::State& state) {
  const PolygonMesh& source = rcp_inputs(state.range(0)).regularized;
  std::int64_t cells = 0;
  for (auto _ : state) {
    // The copies are part of what a generator hands to the constructor; keep them out of the
    // timing so only the topology build is measured.
    state.PauseTiming();
    std::vector<Point> vertices = source.vertices();
    std::vector<int> offsets = source.offsets();
    std::vector<int> cell_vertices = source.cell_vertex_list();
    state.ResumeTiming();
    PolygonMesh mesh(source.domain(), std::move(vertices), std::move(offsets),
                     std::move(cell_vertices));
    cells = mesh.num_cells();
    benchmark::DoNotOptimize(mesh.edges().data());
  }
  set_cells(state, cells);
}

void BM_HexGeneration(benchmark::State& state) {
  MeshSpec spec;
  spec.family = MeshFamily::hex;
  spec.domain = bench_domain();
  spec.size = hex_spacing_for_cells(static_cast<double>(state.range(0)));
  std::int64_t cells = 0;
  for (auto _ : state) {
    GeneratedMesh generated = generate_mesh(spec);
    cells = generated.mesh.num_cells();
    benchmark::DoNotOptimize(generated.mesh.vertices().data());
  }
  set_cells(state, cells);
}

/// Cells per second are cells over wall time (UseRealTime): the generators may use threads, and
/// wall time is what a user waits.
void cell_counts(benchmark::internal::Benchmark* b) {
  b->Unit(benchmark::kMillisecond)->UseRealTime();
  for (std::int64_t n : {1'000, 10'000, 100'000}) b->Arg(n);
}

/// N = 1e6 runs a fixed small number of iterations (a few seconds each).
void large_case(benchmark::internal::Benchmark* b) {
  b->Unit(benchmark::kMillisecond)->UseRealTime()->Arg(1'000'000)->Iterations(2);
}

}  // namespace

BENCHMARK(BM_PoissonDiskSampling)->Apply(cell_counts);
BENCHMARK(BM_PoissonDiskSampling)->Apply(large_case);
BENCHMARK(BM_VoronoiTessellation)->Apply(cell_counts);
BENCHMARK(BM_VoronoiTessellation)->Apply(large_case);
BENCHMARK(BM_Regularization)->Apply(cell_counts);
BENCHMARK(BM_Regularization)->Apply(large_case);
BENCHMARK(BM_RcpGenerationTwoThreads)->Apply(large_case);
BENCHMARK(BM_RcpGeneration)->Apply(cell_counts);
BENCHMARK(BM_RcpGeneration)->Apply(large_case);
BENCHMARK(BM_MeshTopology)->Apply(cell_counts);
BENCHMARK(BM_MeshTopology)->Apply(large_case);
BENCHMARK(BM_HexGeneration)->Apply(cell_counts);
BENCHMARK(BM_HexGeneration)->Apply(large_case);

BENCHMARK_MAIN();
