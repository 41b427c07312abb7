#include "verification/solve/SolveRun.hpp"

#include <cmath>

#include "cg/CgElasticity.hpp"
#include "core/element/ElasticityIntegrator.hpp"
#include "core/problem/AffineField.hpp"
#include "core/problem/ErrorNorms.hpp"
#include "core/problem/ManufacturedSolution.hpp"
#include "core/problem/TimoshenkoBeam.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"

namespace vorodg {

std::unique_ptr<ExactSolution> make_problem(const SolveSettings& s, const Rectangle& domain) {
  const IsotropicElasticity material(s.E, s.nu, s.plane);
  if (s.problem == "beam") {
    const double tol = 1e-12 * domain.scale();
    if (std::abs(domain.x0()) > tol || std::abs(domain.y0() + domain.y1()) > tol)
      throw InputError("problem beam: domain " + domain.to_string() +
                       ", expected [0, L] x [-D/2, D/2] (e.g. --domain 0,-0.5,4,0.5)");
    return std::make_unique<TimoshenkoBeam>(material, domain.width(), domain.height(), s.load);
  }
  if (s.problem == "patch")
    return std::make_unique<AffineField>(material, AffineField::Supports::dirichlet);
  if (s.problem == "patch-mixed")
    return std::make_unique<AffineField>(material, AffineField::Supports::mixed);
  if (s.problem == "patch-traction")
    return std::make_unique<AffineField>(material, AffineField::Supports::traction);
  if (s.problem == "mms") return std::make_unique<ManufacturedSolution>(material, domain);
  throw InputError("problem '" + s.problem +
                   "': expected one of beam, patch, patch-mixed, patch-traction, mms");
}

void require_converged(const SolveResult& r, const SolveSettings& settings) {
  if (!r.dg || r.dg->stop_reason == "converged" || r.dg->stop_reason == "direct") return;
  throw NumericalError(settings.formulation + ": the interface iteration " +
                       (r.dg->stop_reason == "diverged" ? "diverged" : "did not converge") +
                       " (stop reason " + r.dg->stop_reason + " after " +
                       std::to_string(r.dg->iterations) + " iterations, relative change " +
                       fmt(r.dg->last_change, 3) + ", tolerance " + fmt(settings.dg.tolerance, 3) +
                       "); nothing written: raise --max-iter, or --kp");
}

namespace {

/// Runs the formulation and fills the displacement part of the result.
template <class Formulation>
void collect(const Formulation& formulation, const PolygonMesh& mesh, SolveResult& result) {
  for (const auto& [stage, seconds] : formulation.seconds()) result.seconds[stage] = seconds;
  result.dofs = formulation.num_dofs();
  result.free_dofs = formulation.num_free_dofs();
  result.rcond = formulation.factorization().rcond;
  result.factor_nonzeros = formulation.factorization().factor_nonzeros;
  if (formulation.factorization().analysis_shared) result.shared_stages.push_back("analysis");
  result.cell_offsets.assign(mesh.num_cells() + 1, 0);
  for (int c = 0; c < mesh.num_cells(); ++c)
    result.cell_offsets[c + 1] = result.cell_offsets[c] + 2 * mesh.cell_size(c);
  result.cell_dof_values.resize(result.cell_offsets.back());
  result.vertex_displacement = Eigen::Matrix2Xd::Zero(2, mesh.num_vertices());
  for (int c = mesh.num_cells() - 1; c >= 0; --c) {
    const Eigen::VectorXd u = formulation.cell_dofs(c);
    result.cell_dof_values.segment(result.cell_offsets[c], u.size()) = u;
    const auto loop = mesh.cell_vertices(c);
    for (std::size_t k = 0; k < loop.size(); ++k)
      result.vertex_displacement.col(loop[k]) = u.segment<2>(2 * k);
  }
}

}  // namespace

const Choices& formulation_choices() {
  static const Choices choices = [] {
    Choices out{{"cg", "continuous Galerkin on the vertex DOFs"}};
    for (const DgFormulationEntry& e : dg_formulations()) out.push_back({e.name, e.doc});
    return out;
  }();
  return choices;
}

const Choices& penalty_choices() {
  static const Choices choices = choice_table(R"(
h-avg    eps = k_p E / h_avg (the report's f(h) = 1/h)
local-h  eps = k_p E / h_F, h_F = (|K_1| + |K_2|) / (2 |F|) per interface
fixed-h  eps = k_p E / H, H the domain's shorter side (not refined with the mesh)
auto     eps = k_p times the proven coercive bound from the cells' trace constants
)");
  return choices;
}

const Choices& traction_choices() {
  static const Choices choices = choice_table(R"(
point  each cell's own stress at the edge points (one-sided limits of the gradients)
fan    each cell's own stress averaged over its fan triangle on the edge
mean   each cell's mean stress (the report's Eq. 29)
)");
  return choices;
}

namespace {
constexpr PenaltyScaling kPenalties[] = {PenaltyScaling::h_avg, PenaltyScaling::local_h,
                                         PenaltyScaling::fixed_h, PenaltyScaling::coercive};
constexpr TractionKind kTractions[] = {TractionKind::point, TractionKind::fan, TractionKind::mean};
}  // namespace

PenaltyScaling parse_penalty(const std::string& name) {
  return parse_enum(penalty_choices(), kPenalties, name);
}
std::string penalty_name(PenaltyScaling scaling) {
  return enum_name(penalty_choices(), kPenalties, scaling);
}
TractionKind parse_traction(const std::string& name) {
  return parse_enum(traction_choices(), kTractions, name);
}
std::string traction_name(TractionKind kind) {
  return enum_name(traction_choices(), kTractions, kind);
}

DgOptions dg_options(const SolveSettings& settings) {
  DgOptions options = settings.dg;
  options.formulation = settings.formulation == "cg" ? "dg-penalty" : settings.formulation;
  options.ordering = settings.solver.ordering;
  return options;
}

LinearSolverOptions cg_solver(const SolveSettings& settings) {
  LinearSolverOptions solver = settings.solver;
  if (settings.problem.starts_with("patch") && solver.kind == LinearSolverKind::automatic)
    solver.kind = LinearSolverKind::cholmod;
  return solver;
}

namespace {

/// The run's element table: the one shared by the runs on the mesh, or its own (`own`).
const ElementTable& obtain_table(const PolygonMesh& mesh, const SolveSettings& settings,
                                 const BoundaryValueProblem& problem, SharedMeshWork* shared,
                                 std::unique_ptr<ElementTable>& own, SolveResult& result) {
  if (shared) {
    if (&shared->mesh() != &mesh) throw NumericalError("internal: shared work of another mesh");
    bool reused = false;
    const ElementTable& table =
        shared->element_table(settings.element, result.seconds["element"], reused);
    if (reused) result.shared_stages.push_back("element");
    return table;
  }
  Stopwatch clock;
  ElementOptions options = settings.element;  // a table of its own keeps only what it needs
  options.shape_values = problem.has_body_force();
  own = std::make_unique<ElementTable>(mesh, options);
  result.seconds["element"] = clock.seconds();
  return *own;
}

void record_element_quality(const ElementTable& table, SolveResult& result) {
  const PolygonMesh& mesh = table.mesh();
  for (int c = 0; c < mesh.num_cells(); ++c) {
    result.max_divergence_defect = std::max(
        result.max_divergence_defect, table.divergence_defect(c) / std::sqrt(mesh.cell_area(c)));
    result.min_moment_rcond = c == 0 ? table.min_moment_rcond(c)
                                     : std::min(result.min_moment_rcond, table.min_moment_rcond(c));
  }
}

/// Weight functions up to this size stay alive through the factorization when the errors need
/// them afterwards; larger ones are released and rebuilt for the errors.
constexpr std::size_t kKeptWeightsBudget = std::size_t{256} << 20;

/// CG: assemble, keep the cell mean strain operators, then (with a table of its own) release the
/// table's point values, and its weight functions unless the errors need them and they fit the
/// budget, before the factorization, the largest memory peak of a solve.
ElasticityIntegrator::MeanStrainOperators solve_cg(const ElasticityIntegrator& integrator,
                                                   const ExactSolution& problem,
                                                   const SolveSettings& settings,
                                                   SymbolicAnalyses* analyses,
                                                   ElementTable* own_table, SolveResult& result) {
  const ElementTable& table = integrator.table();
  CgElasticity formulation(table, integrator, problem, settings.element.threads,
                           cg_solver(settings));
  formulation.share_analyses(analyses);
  formulation.setup_system();
  formulation.assemble_system();
  Stopwatch clock;
  auto mean_strain = integrator.all_mean_strain_operators(settings.element.threads);
  if (own_table) {
    own_table->release_point_values();
    // The errors need the weights again: rebuilding them cost 0.7-1.4 s at 1e5 cells, keeping
    // them 90 MB there; above the budget (0.9 GB at 1e6 cells) the factorization's peak wins.
    if (!settings.errors || own_table->weights_bytes() > kKeptWeightsBudget)
      own_table->release_weights();
  }
  result.seconds["cell_means"] = clock.seconds();
  formulation.solve();
  collect(formulation, table.mesh(), result);
  result.solver = formulation.solver();
  result.amg = formulation.amg_report();
  result.edge_gaps.assign(table.mesh().num_edges(), 0.0);
  if (own_table && settings.errors && own_table->weights_released()) {
    clock.restart();
    own_table->restore_weights();
    result.seconds["error_weights"] = clock.seconds();
  }
  return mean_strain;
}

ElasticityIntegrator::MeanStrainOperators solve_dg(const ElasticityIntegrator& integrator,
                                                   const ExactSolution& problem,
                                                   const SolveSettings& settings,
                                                   SymbolicAnalyses* analyses,
                                                   SolveResult& result) {
  const ElementTable& table = integrator.table();
  DgElasticity formulation(table, integrator, problem, dg_options(settings),
                           settings.element.threads);
  formulation.share_analyses(analyses);
  formulation.run();
  Stopwatch clock;
  auto mean_strain = integrator.all_mean_strain_operators(settings.element.threads);
  result.seconds["cell_means"] = clock.seconds();
  collect(formulation, table.mesh(), result);
  result.edge_gaps = formulation.edge_gaps();
  result.dg = formulation.report();
  return mean_strain;
}

/// A cell's own displacement DOFs of a solve.
Eigen::VectorXd cell_dofs(const PolygonMesh& mesh, const SolveResult& result, int c) {
  return result.cell_dof_values.segment(result.cell_offsets[c], 2 * mesh.cell_size(c));
}

/// The cell mean stresses (ElasticityIntegrator::mean_stress).
void measure_mean_stresses(const ElasticityIntegrator& integrator,
                           const ElasticityIntegrator::MeanStrainOperators& mean_strain,
                           SolveResult& result) {
  const PolygonMesh& mesh = integrator.table().mesh();
  result.cell_mean_stress.resize(mesh.num_cells());
  for (int c = 0; c < mesh.num_cells(); ++c)
    result.cell_mean_stress[c] = integrator.mean_stress(mean_strain, c, cell_dofs(mesh, result, c));
}

/// The errors against the exact solution, on the error rule's own points.
void measure_errors(const ElasticityIntegrator& integrator, const ExactSolution& problem,
                    const SolveSettings& settings,
                    const ElasticityIntegrator::MeanStrainOperators& mean_strain,
                    SolveResult& result) {
  Stopwatch clock;
  const ElementTable& table = integrator.table();
  const PolygonMesh& mesh = table.mesh();
  CellDilatationMean dilatation_mean;
  if (settings.mean_dilation)
    dilatation_mean = [&](int c, const Eigen::VectorXd& u) {
      const auto op = mean_strain.block(c);
      return op.row(0).dot(u) + op.row(1).dot(u);
    };
  const ErrorReport errors = compute_errors(
      table, problem, [&](int c) { return cell_dofs(mesh, result, c); }, settings.energy_error,
      settings.element.threads, dilatation_mean);
  result.errors_measured = true;
  result.l2_error = errors.l2_error;
  result.energy_error = errors.energy_error;
  result.cell_l2_density = errors.cell_l2_density;
  result.cell_energy_density = errors.cell_energy_density;
  measure_mean_stresses(integrator, mean_strain, result);  // timed with the errors as before
  result.seconds["error"] = clock.seconds();
}

}  // namespace

SolveResult run_solve(const PolygonMesh& mesh, const SolveSettings& settings,
                      SharedMeshWork* shared) {
  const bool cg = settings.formulation == "cg";
  if (!cg && settings.solver.kind == LinearSolverKind::amg_cg)
    throw InputError("solver amg-cg with formulation " + settings.formulation +
                     ": expected cg (DG systems are solved with cholmod)");
  SolveResult result;
  const auto problem = make_problem(settings, mesh.domain());
  std::unique_ptr<ElementTable> own_table;
  const ElementTable& table = obtain_table(mesh, settings, *problem, shared, own_table, result);
  record_element_quality(table, result);
  const ElasticityIntegrator integrator(table, problem->material(), settings.mean_dilation);
  SymbolicAnalyses* analyses = shared ? &shared->analyses() : nullptr;
  const auto mean_strain =
      cg ? solve_cg(integrator, *problem, settings, analyses, own_table.get(), result)
         : solve_dg(integrator, *problem, settings, analyses, result);
  if (settings.errors)
    measure_errors(integrator, *problem, settings, mean_strain, result);
  else
    measure_mean_stresses(integrator, mean_strain, result);
  return result;
}

}  // namespace vorodg
