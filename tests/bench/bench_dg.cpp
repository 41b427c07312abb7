// DG iteration cost against the factorization: the beam on rcp meshes with dg-nitsche
// and dg-al (k_p = 1e3 E); counters give the analysis and factorization seconds of a + eps P and
// the seconds of one iteration (back-solve + interface-load update). Target at 1e5 cells: one
// iteration <= 10% of the factorization. BM_DgAmgCg: whether AMG-preconditioned CG converges on
// a + eps P (docs/solvers.md). BM_StudyOnOneMesh: the seven runs fig26 makes on each mesh
// (cg, dg-nitsche at four k_p, dg-al, dg-sipg), alone or sharing the mesh's element table and
// symbolic analyses (SharedMeshWork), one thread as in a study.
#include <benchmark/benchmark.h>

#include <cmath>

#include "core/meshgen/MeshFamily.hpp"
#include "core/solve/AmgConjugateGradient.hpp"
#include "core/util/BlasInfo.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Stopwatch.hpp"
#include "interfaces/TraceConstants.hpp"
#include "verification/solve/SolveRun.hpp"

namespace {

using namespace vorodg;

/// The rcp beam mesh of about `cells` cells (seed 5).
GeneratedMesh rcp_beam_mesh(std::int64_t cells) {
  MeshSpec spec;
  spec.family = MeshFamily::rcp;
  spec.domain = Rectangle(0.0, -0.5, 4.0, 0.5);
  spec.size = std::sqrt(0.7 * spec.domain.area() / static_cast<double>(cells));
  spec.seed = 5;
  return generate_mesh(spec);
}

void BM_DgIteration(benchmark::State& state) {
  const GeneratedMesh mesh = rcp_beam_mesh(state.range(0));
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
  // Everything the DG operator's assembly costs: cell matrices, penalties, the sparse matrix.
  const double assembly = r.seconds["cell_matrices"] + r.seconds["penalty"] + r.seconds["assembly"];
  state.counters["assembly"] = assembly;
  state.counters["assembly_over_factorization"] = assembly / r.seconds["factorization"];
}

void BM_StudyOnOneMesh(benchmark::State& state) {
  const GeneratedMesh mesh = rcp_beam_mesh(state.range(0));
  const bool share = state.range(1) == 1;
  std::vector<SolveSettings> runs;
  const auto add = [&](const std::string& formulation, double kp) {
    SolveSettings s;
    s.formulation = formulation;
    s.dg.kp = kp;
    if (formulation == "dg-sipg") {
      s.dg.penalty = PenaltyScaling::h_avg;
      s.dg.traction = TractionKind::mean;
    }
    runs.push_back(s);
  };
  add("cg", 1.0);
  for (double kp : {1e1, 1e2, 1e3, 1e4}) add("dg-nitsche", kp);
  add("dg-al", 1e3);
  add("dg-sipg", 1e3);
  const ScopedBlasThreads blas(1);  // as a study runs
  double l2 = 0.0;
  for (auto _ : state) {
    std::optional<SharedMeshWork> shared;
    if (share) shared.emplace(mesh.mesh);
    for (const SolveSettings& s : runs)
      l2 += run_solve(mesh.mesh, s, shared ? &*shared : nullptr).l2_error;
  }
  benchmark::DoNotOptimize(l2);
  state.counters["cells"] = mesh.mesh.num_cells();
}

/// The coercive penalty's per-cell eigenproblems against the element table's setup, on the
/// same rcp mesh with one thread: range(1) = 0 fan stresses (the dg-sipg default), 1 point
/// stresses, 2 mean stresses. Target: <= 15% of the element setup at 1e5 cells.
void BM_TraceConstants(benchmark::State& state) {
  const GeneratedMesh mesh = rcp_beam_mesh(state.range(0));
  Stopwatch clock;
  const ElementTable table(mesh.mesh, ElementOptions{});
  const double element_seconds = clock.seconds();
  const IsotropicElasticity material(1.0, 0.3, PlaneModel::stress);
  const ElasticityIntegrator integrator(table, material, false);
  const auto stiffness = integrator.all_cell_matrices(1);
  const DgSpace space(mesh.mesh);
  const InterfaceOperators ops(space, integrator, table);
  const TractionKind kind = state.range(1) == 0   ? TractionKind::fan
                            : state.range(1) == 1 ? TractionKind::point
                                                  : TractionKind::mean;
  double seconds = 0.0;
  for (auto _ : state) {
    clock.restart();
    const TraceConstants constants(ops, stiffness, kind, 1);
    seconds = clock.seconds();
    benchmark::DoNotOptimize(constants.constant(0, 0));
  }
  state.counters["cells"] = mesh.mesh.num_cells();
  state.counters["element_setup"] = element_seconds;
  state.counters["trace_constants"] = seconds;
  state.counters["over_element_setup"] = seconds / element_seconds;
}

/// Does AMG-preconditioned CG still converge on the DG operator a + eps P (dg-nitsche's, on the
/// rcp beam) as k_p grows? range(1) is log10 k_p. One CG solve of a + eps P against a right-hand
/// side of ones, tolerance 1e-8, at most 1000 iterations; `converged` 0 where it did not.
/// CHOLMOD's analysis and factorization of the same matrix are the counters to compare with.
void BM_DgAmgCg(benchmark::State& state) {
  const GeneratedMesh mesh = rcp_beam_mesh(state.range(0));
  SolveSettings settings;
  settings.formulation = "dg-nitsche";
  settings.dg.kp = std::pow(10.0, static_cast<double>(state.range(1)));
  const auto problem = make_problem(settings, mesh.mesh.domain());
  const ElementTable table(mesh.mesh, ElementOptions{});
  const ElasticityIntegrator integrator(table, problem->material(), false);
  DgElasticity dg(table, integrator, *problem, dg_options(settings), 2);
  dg.setup_system();
  dg.assemble_system();
  const Eigen::SparseMatrix<double> lower = dg.system_matrix().triangularView<Eigen::Lower>();
  const Eigen::VectorXd rhs = Eigen::VectorXd::Ones(lower.rows());
  bool converged = true;
  AmgConjugateGradient amg;
  for (auto _ : state) {
    amg.setup(lower, Eigen::VectorXd(), {.tolerance = 1e-8, .max_iterations = 1000});
    try {
      benchmark::DoNotOptimize(amg.solve(rhs));
    } catch (const NumericalError&) {
      converged = false;
    }
  }
  SparseCholesky cholesky;
  const FactorizationReport factor = cholesky.factorize(lower);
  state.counters["dofs"] = static_cast<double>(lower.rows());
  state.counters["converged"] = converged;
  state.counters["iterations"] = amg.report().iterations;
  state.counters["amg_setup"] = amg.report().seconds_setup;
  state.counters["cg"] = amg.report().seconds_solve;
  state.counters["analysis"] = factor.seconds_analyze;
  state.counters["factorization"] = factor.seconds_factorize;
}

}  // namespace

BENCHMARK(BM_DgAmgCg)
    ->ArgNames({"cells", "log10_kp"})
    ->Args({10000, 1})
    ->Args({100000, 1})
    ->Args({10000, 3})
    ->Args({100000, 3})
    ->Args({10000, 5})  // does not converge: 1000 iterations (at 1e5 cells they would take 12 min)
    ->Iterations(1)
    ->Repetitions(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

BENCHMARK(BM_TraceConstants)
    ->Args({100000, 0})
    ->Args({100000, 1})
    ->Args({100000, 2})
    ->Iterations(1)
    ->Repetitions(3)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

BENCHMARK(BM_StudyOnOneMesh)
    ->ArgNames({"cells", "shared"})
    ->Args({10000, 0})
    ->Args({10000, 1})
    ->Args({30000, 0})
    ->Args({30000, 1})
    ->Iterations(1)
    ->Repetitions(3)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

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
