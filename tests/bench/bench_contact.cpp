// Cost of contact per explicit step against the number of surface cells N = 1e3 .. 1e6, with a
// least-squares fit of time = c N (benchmark's ->Complexity(oN)), to show the search is linear:
//   BM_ContactGrid    the broad phase alone: ContactGrid::find on the cells' boxes
//   BM_ContactSearch  SurfaceContact::find_pairs: boxes from the pair positions, grid, and the
//                     neighbour filter (cells that share a vertex are dropped)
//   BM_ContactStep    SurfaceContact::add_forces: the search plus both passes of
//                     vertex-in-polygon on every candidate pair and the penalty law
// The scene is the worst case for the search: an rcp mesh on the 4 x 1 domain with every cell
// marked as a surface cell, each vertex moved by up to 5% of d (the same for all its pairs), so
// that every cell's box overlaps those of its neighbours and of the cells beyond them. Counters:
// cells (N), pairs per cell, and the time per cell (s/cell, i.e. the inverse rate).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Random.hpp"
#include "dynamics/contact/SurfaceContact.hpp"

namespace {

using namespace vorodg;

constexpr std::uint64_t kSeed = 20240607;

struct Scene {
  std::int64_t target = 0;
  PolygonMesh mesh;
  std::unique_ptr<SurfaceCells> surface;
  std::vector<Point> x;  // per (cell, vertex) pair
  std::vector<Box> boxes;
};

/// The scene for about n cells, built once per n (only the last one is kept: 1e6 cells take a
/// few hundred MB).
const Scene& scene(std::int64_t n) {
  static std::unique_ptr<Scene> cached;
  if (cached && cached->target == n) return *cached;
  cached.reset();
  auto s = std::make_unique<Scene>();
  s->target = n;
  MeshSpec spec;
  spec.domain = Rectangle(0.0, 0.0, 4.0, 1.0);
  spec.size = std::sqrt(0.7 * spec.domain.area() / static_cast<double>(n));  // ~n cells
  spec.seed = kSeed;
  s->mesh = generate_mesh(spec).mesh;
  s->surface = std::make_unique<SurfaceCells>(s->mesh);
  for (int c = 0; c < s->mesh.num_cells(); ++c) s->surface->add(c);
  Random random(kSeed);
  std::vector<Point> moved(s->mesh.num_vertices());
  for (int v = 0; v < s->mesh.num_vertices(); ++v)
    moved[v] = s->mesh.vertex(v) +
               0.05 * spec.size * Point(random.uniform(-1.0, 1.0), random.uniform(-1.0, 1.0));
  for (int v : s->mesh.cell_vertex_list()) s->x.push_back(moved[v]);
  for (int c = 0; c < s->mesh.num_cells(); ++c) {
    Box b;
    for (int p = s->mesh.offsets()[c]; p < s->mesh.offsets()[c + 1]; ++p) b.extend(s->x[p]);
    s->boxes.push_back(b);
  }
  cached = std::move(s);
  return *cached;
}

void set_counters(benchmark::State& state, std::int64_t cells, std::size_t pairs) {
  state.SetComplexityN(cells);
  state.counters["cells"] = static_cast<double>(cells);
  state.counters["pairs_per_cell"] = static_cast<double>(pairs) / static_cast<double>(cells);
  state.counters["time_per_cell"] =
      benchmark::Counter(static_cast<double>(cells), benchmark::Counter::kIsIterationInvariantRate |
                                                         benchmark::Counter::kInvert);
}

PenaltyContact fixed_law() {
  PenaltyParameters p;
  p.stiffness = 1.0;
  return PenaltyContact(p);
}

void BM_ContactGrid(benchmark::State& state) {
  const Scene& s = scene(state.range(0));
  ContactGrid grid(s.mesh.h_avg());
  std::size_t pairs = 0;
  for (auto _ : state) {
    pairs = grid.find(s.boxes).size();
    benchmark::DoNotOptimize(pairs);
  }
  set_counters(state, s.mesh.num_cells(), pairs);
}

void BM_ContactSearch(benchmark::State& state) {
  const Scene& s = scene(state.range(0));
  SurfaceContact contact(fixed_law(), s.mesh.h_avg());
  std::size_t pairs = 0;
  for (auto _ : state) {
    pairs = contact.find_pairs(*s.surface, s.x).size();
    benchmark::DoNotOptimize(pairs);
  }
  set_counters(state, s.surface->size(), pairs);
}

void BM_ContactStep(benchmark::State& state) {
  const Scene& s = scene(state.range(0));
  SurfaceContact contact(fixed_law(), s.mesh.h_avg());
  PairState pair_state;
  pair_state.position = s.x;
  std::vector<Point> force(s.x.size(), Point::Zero());
  ContactReport report;
  for (auto _ : state) {
    report = contact.add_forces(*s.surface, pair_state, force);
    benchmark::DoNotOptimize(force.data());
  }
  set_counters(state, s.surface->size(), static_cast<std::size_t>(report.candidates));
  state.counters["contacts"] = report.contacts;
}

void sizes(benchmark::internal::Benchmark* b) {
  for (std::int64_t n : {1000, 3000, 10000, 30000, 100000, 300000, 1000000}) b->Arg(n);
  b->Unit(benchmark::kMillisecond)->Complexity(benchmark::oN);
}

BENCHMARK(BM_ContactGrid)->Apply(sizes);
BENCHMARK(BM_ContactSearch)->Apply(sizes);
BENCHMARK(BM_ContactStep)->Apply(sizes);

}  // namespace

BENCHMARK_MAIN();
