#include "dg/DgElasticity.hpp"

#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>

#include "core/element/LoadIntegrator.hpp"
#include "core/quadrature/TriangleRule.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "dg/DgSystemAssembly.hpp"

namespace vorodg {
namespace {

/// `auto` means node-metis for DG: its factor serves every iteration's solve, and a smaller
/// factor makes each of them cheaper (node-amd pays off only for one solve).
FillOrdering dg_ordering(FillOrdering ordering) {
  return ordering == FillOrdering::automatic ? FillOrdering::node_metis : ordering;
}

}  // namespace

DgElasticity::DgElasticity(const ElementTable& table, const ElasticityIntegrator& integrator,
                           const BoundaryValueProblem& problem, const DgOptions& options,
                           int threads)
    : table_(table),
      integrator_(integrator),
      problem_(problem),
      options_(options),
      threads_(std::max(threads, 1)),
      space_(table.mesh()),
      ops_(space_, integrator, table),
      formulation_(make_dg_formulation(options)),
      traction_(options.traction ? *options.traction : formulation_->default_traction()) {
  const double kp = penalty_multiplier(options);
  if (!(kp > 0.0) || !std::isfinite(kp))
    throw InputError("penalty k_p = " + fmt(kp) + ": expected k_p > 0");
  if (!(options.tolerance > 0.0)) throw InputError("DG tolerance: expected > 0");
  if (options.max_iterations < 1) throw InputError("DG maximum iterations: expected >= 1");
  formulation_->check_options(options);
}

void DgElasticity::run() {
  setup_system();
  assemble_system();
  solve();
}

PenaltyScaling penalty_scaling(const DgOptions& options) {
  if (options.penalty) return *options.penalty;
  return make_dg_formulation(options)->default_scaling();
}

double penalty_multiplier(const DgOptions& options) {
  if (options.kp) return *options.kp;
  return penalty_scaling(options) == PenaltyScaling::coercive ? 1.0 : 1e3;
}

TractionKind interface_traction(const DgOptions& options) {
  if (options.traction) return *options.traction;
  return make_dg_formulation(options)->default_traction();
}

void DgElasticity::setup_system() {
  Stopwatch clock;
  // Every cell's copy of a vertex on a Dirichlet side carries the prescribed displacement.
  constraints_.emplace(
      table_.mesh(), problem_, [&](int c, int k) { return space_.dof(c, k); }, num_dofs());
  seconds_["setup"] = clock.seconds();
}

bool DgElasticity::symmetric() const {
  return formulation_->symmetric();
}

DgTermContext DgElasticity::term_context() const {
  return {space_, ops_, *penalty_, integrator_, options_, traction_, threads_};
}

void DgElasticity::assemble_system() {
  Stopwatch clock;
  const PolygonMesh& mesh = table_.mesh();
  // a(u, v): the shared cell kernel, block by block (each cell owns its DOFs).
  const auto cells = integrator_.all_cell_matrices(threads_);
  seconds_["cell_matrices"] = clock.seconds();
  clock.restart();
  penalty_ = std::make_unique<InterfacePenalty>(ops_, integrator_, cells, penalty_scaling(options_),
                                                penalty_multiplier(options_),
                                                options_.weighted_average, traction_, threads_);
  seconds_["penalty"] = clock.seconds();
  clock.restart();
  DgSystem system = assemble_dg_system(
      space_, *constraints_, cells, [&](std::size_t i) { return interface_matrix(i); }, symmetric(),
      threads_);
  A_ = std::move(system.matrix);
  A_fixed_ = std::move(system.fixed);

  // l(v) on the cells' own copies.
  Eigen::VectorXd f = Eigen::VectorXd::Zero(num_dofs());
  const DofOf cell_dof = [&](int c, int k) { return space_.dof(c, k); };
  add_body_force(table_, problem_, cell_dof, f);
  add_boundary_tractions(mesh, problem_, cell_dof, f);
  load_ = constraints_->restrict(f) - A_fixed_ * constraints_->prescribed();
  formulation_->prepare(term_context());
  seconds_["assembly"] = clock.seconds();
}

/// The interface terms that stay on the left side, on interface i's two cells' DOFs:
/// eps int [u].[v] (exact with two points: jumps are linear along the edge), and the
/// formulation's own (SIPG's consistency and symmetry terms).
Eigen::MatrixXd DgElasticity::interface_matrix(std::size_t i) const {
  Eigen::MatrixXd local = ops_.penalty_block(space_.interfaces()[i], penalty_->eps(i));
  formulation_->add_interface_block(term_context(), i, local);
  return local;
}

void DgElasticity::solve() {
  Stopwatch clock;
  report_.penalty = median_penalty();
  const bool symmetric = this->symmetric();
  SparseCholesky cholesky;
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  if (symmetric) {
    try {
      factorization_ = cholesky.factorize(
          A_, {.ordering = dg_ordering(options_.ordering), .shared_analyses = shared_analyses_});
    } catch (const NumericalError&) {
      const std::optional<std::string> hint = formulation_->not_definite_hint(options_);
      if (!hint) throw;
      throw NumericalError(*hint);
    }
    seconds_["analysis"] = factorization_.seconds_analyze;
    seconds_["factorization"] = factorization_.seconds_factorize;
  } else {
    lu.compute(A_);
    if (lu.info() != Eigen::Success)
      throw NumericalError("the non-symmetric DG matrix could not be factored (singular)");
    seconds_["factorization"] = clock.seconds();
  }
  auto back_solve = [&](const Eigen::VectorXd& rhs) -> Eigen::VectorXd {
    if (symmetric) return cholesky.solve(rhs);
    Eigen::VectorXd x = lu.solve(rhs);
    if (!x.allFinite()) throw NumericalError("the sparse solve produced non-finite values");
    return x;
  };
  auto expand = [&](const Eigen::VectorXd& free_values) {
    return constraints_->expand(free_values);
  };

  clock.restart();
  u_ = expand(back_solve(load_));  // penalty / sipg: the answer; al, nitsche: the first iterate
  report_.iterations = 1;
  report_.stop_reason = "direct";
  const bool iterative = formulation_->iterative();
  const DgTermContext context = term_context();
  double smallest_change = INFINITY;
  if (iterative && report_.iterations >= options_.max_iterations)
    report_.stop_reason = "max-iterations";
  while (iterative && report_.iterations < options_.max_iterations) {
    formulation_->update(context, u_);  // al: lambda <- lambda + eps [u]
    const Eigen::VectorXd next = expand(
        back_solve(load_ + constraints_->restrict(formulation_->interface_load(context, u_))));
    const double change = (next - u_).norm() / std::max(next.norm(), 1e-300);
    u_ = next;
    ++report_.iterations;
    report_.last_change = change;
    smallest_change = std::min(smallest_change, change);
    if (!std::isfinite(change) || (report_.iterations > 5 && change > 1e3 * smallest_change) ||
        change > 1e6) {
      report_.stop_reason = "diverged";
      break;
    }
    if (change < options_.tolerance) {
      report_.stop_reason = "converged";
      break;
    }
    report_.stop_reason = "max-iterations";  // unless the next pass converges
  }
  seconds_["solve"] = clock.seconds();
  report_.seconds_per_iteration = clock.seconds() / report_.iterations;
  measure_gap();
}

double DgElasticity::median_penalty() const {
  std::vector<double> eps;
  for (std::size_t i = 0; i < space_.interfaces().size(); ++i) eps.push_back(penalty_->eps(i));
  if (eps.empty()) return 0.0;
  std::nth_element(eps.begin(), eps.begin() + eps.size() / 2, eps.end());
  return eps[eps.size() / 2];
}

void DgElasticity::measure_gap() {
  const SegmentRule& rule = gauss2_segment();
  double gap = 0.0, mean = 0.0;
  for (const Interface& f : space_.interfaces())
    for (int q = 0; q < 2; ++q) {
      const double t = rule.t[q], w = rule.weights[q] * f.length;
      Eigen::Vector2d u[2];
      for (int s = 0; s < 2; ++s)
        u[s] = (1 - t) * u_.segment<2>(f.dof_v0[s]) + t * u_.segment<2>(f.dof_v1[s]);
      gap += w * (u[0] - u[1]).squaredNorm();
      mean += w * (0.5 * (u[0] + u[1])).squaredNorm();
    }
  report_.gap_norm = std::sqrt(gap);
  report_.relative_gap = mean > 0 ? std::sqrt(gap / mean) : report_.gap_norm;
}

std::vector<double> DgElasticity::edge_gaps() const {
  std::vector<double> gaps(table_.mesh().num_edges(), 0.0);
  for (const Interface& f : space_.interfaces())
    for (double t : {0.0, 1.0}) {
      const Eigen::Vector2d u0 =
          (1 - t) * u_.segment<2>(f.dof_v0[0]) + t * u_.segment<2>(f.dof_v1[0]);
      const Eigen::Vector2d u1 =
          (1 - t) * u_.segment<2>(f.dof_v0[1]) + t * u_.segment<2>(f.dof_v1[1]);
      gaps[f.edge] = std::max(gaps[f.edge], (u0 - u1).norm());
    }
  return gaps;
}

}  // namespace vorodg
