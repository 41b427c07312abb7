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
constexpr int kConsistencyChunk = 1024;  // interfaces per parallel work item
}  // namespace

DgMethod parse_dg_method(const std::string& formulation) {
  if (formulation == "dg-penalty") return DgMethod::penalty;
  if (formulation == "dg-al") return DgMethod::augmented_lagrangian;
  if (formulation == "dg-nitsche") return DgMethod::nitsche;
  if (formulation == "dg-sipg") return DgMethod::sipg;
  throw InputError("formulation '" + formulation +
                   "': expected cg, dg-penalty, dg-al, dg-nitsche or dg-sipg");
}

DgElasticity::DgElasticity(const ElementTable& table, const ElasticityIntegrator& integrator,
                           const BoundaryValueProblem& problem, const DgOptions& options,
                           int threads)
    : table_(table),
      integrator_(integrator),
      problem_(problem),
      options_(options),
      threads_(std::max(threads, 1)),
      space_(table.mesh()),
      ops_(space_, integrator, table) {
  const double kp = penalty_multiplier(options);
  if (!(kp > 0.0) || !std::isfinite(kp))
    throw InputError("penalty k_p = " + fmt(kp) + ": expected k_p > 0");
  if (!(options.tolerance > 0.0)) throw InputError("DG tolerance: expected > 0");
  if (options.max_iterations < 1) throw InputError("DG maximum iterations: expected >= 1");
  if (options.sipg_sign != -1 && options.sipg_sign != 1)
    throw InputError("dg-sipg sign " + std::to_string(options.sipg_sign) +
                     ": expected -1 (symmetric) or +1 (non-symmetric)");
}

void DgElasticity::run() {
  setup_system();
  assemble_system();
  solve();
}

PenaltyScaling penalty_scaling(const DgOptions& options) {
  if (options.penalty) return *options.penalty;
  return options.method == DgMethod::sipg ? PenaltyScaling::coercive : PenaltyScaling::h_avg;
}

double penalty_multiplier(const DgOptions& options) {
  if (options.kp) return *options.kp;
  return penalty_scaling(options) == PenaltyScaling::coercive ? 1.0 : 1e3;
}

TractionKind interface_traction(const DgOptions& options) {
  if (options.traction) return *options.traction;
  return options.method == DgMethod::sipg ? TractionKind::fan : TractionKind::mean;
}

void DgElasticity::setup_system() {
  Stopwatch clock;
  // Every cell's copy of a vertex on a Dirichlet side carries the prescribed displacement.
  constraints_.emplace(
      table_.mesh(), problem_, [&](int c, int k) { return space_.dof(c, k); }, num_dofs());
  seconds_["setup"] = clock.seconds();
}

bool DgElasticity::symmetric() const {
  return !(options_.method == DgMethod::sipg && options_.sipg_sign > 0);
}

void DgElasticity::assemble_system() {
  Stopwatch clock;
  const PolygonMesh& mesh = table_.mesh();
  // a(u, v): the shared cell kernel, block by block (each cell owns its DOFs).
  const auto cells = integrator_.all_cell_matrices(threads_);
  seconds_["cell_matrices"] = clock.seconds();
  clock.restart();
  penalty_ = std::make_unique<InterfacePenalty>(
      ops_, integrator_, cells, penalty_scaling(options_), penalty_multiplier(options_),
      options_.weighted_average, interface_traction(options_), threads_);
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
  lambda_.assign(2 * space_.interfaces().size(), Eigen::Vector2d::Zero());
  if (options_.method == DgMethod::nitsche) build_consistency();
  seconds_["assembly"] = clock.seconds();
}

/// The interface terms that stay on the left side, on interface i's two cells' DOFs:
/// eps int [u].[v] (exact with two points: jumps are linear along the edge), and for SIPG
/// -int {sigma(u)}n.[v] + s int {sigma(v)}n.[u].
Eigen::MatrixXd DgElasticity::interface_matrix(std::size_t i) const {
  const Interface& f = space_.interfaces()[i];
  Eigen::MatrixXd local = ops_.penalty_block(f, penalty_->eps(i));
  if (options_.method == DgMethod::sipg) {
    const Eigen::MatrixXd JT = consistency_block(i, interface_traction(options_));
    local += -JT + options_.sipg_sign * JT.transpose();
  }
  return local;
}

/// The interface terms that move to the right side: -int lambda.[v] (al) or
/// +int {sigma(u)} n.[v] (nitsche, the operator built once), restricted to the free DOFs.
Eigen::VectorXd DgElasticity::interface_load(const Eigen::VectorXd& u) {
  if (options_.method == DgMethod::nitsche) return constraints_->restrict(consistency_ * u);
  Eigen::VectorXd g = Eigen::VectorXd::Zero(num_dofs());
  const SegmentRule& rule = gauss2_segment();
  const auto& faces = space_.interfaces();
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const Interface& f = faces[i];
    const std::vector<int> dofs = ops_.dofs(f);
    Eigen::VectorXd local = Eigen::VectorXd::Zero(dofs.size());
    for (int q = 0; q < 2; ++q)
      local -=
          rule.weights[q] * f.length * ops_.jump(f, rule.t[q]).transpose() * lambda_[2 * i + q];
    for (std::size_t k = 0; k < dofs.size(); ++k) g[dofs[k]] += local[k];
  }
  return constraints_->restrict(g);
}

/// int_F {sigma(u)}_w n . [v] on interface i as a block on its two cells' DOFs, with the two-point
/// rule (exact for the fan and mean stresses, which are constant along the edge and so are
/// computed once).
Eigen::MatrixXd DgElasticity::consistency_block(std::size_t i, TractionKind kind) const {
  return ops_.consistency_block(space_.interfaces()[i], kind, penalty_->weights(i));
}

/// int {sigma(u)} n.[v] as a matrix on all DOFs. Only the rows of the edge's end vertices are
/// non-zero in a block ([v] lives there), so exact zeros are left out: a product with the matrix
/// adds the same terms in the same order either way.
void DgElasticity::build_consistency() {
  const TractionKind kind = interface_traction(options_);
  const auto& faces = space_.interfaces();
  const int n = static_cast<int>(faces.size());
  std::vector<std::vector<Eigen::Triplet<double>>> parts((n + kConsistencyChunk - 1) /
                                                         kConsistencyChunk);
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads_)
  for (int part = 0; part < static_cast<int>(parts.size()); ++part)
    for (int i = part * kConsistencyChunk; i < std::min(n, (part + 1) * kConsistencyChunk); ++i) {
      const std::vector<int> dofs = ops_.dofs(faces[i]);
      const Eigen::MatrixXd local = consistency_block(i, kind);
      for (std::size_t j = 0; j < dofs.size(); ++j)
        for (std::size_t r = 0; r < dofs.size(); ++r)
          if (local(r, j) != 0.0) parts[part].emplace_back(dofs[r], dofs[j], local(r, j));
    }
  std::vector<Eigen::Triplet<double>> triplets;  // in interface order, as the sums must run
  for (const auto& part : parts) triplets.insert(triplets.end(), part.begin(), part.end());
  consistency_.resize(num_dofs(), num_dofs());
  consistency_.setFromTriplets(triplets.begin(), triplets.end());
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
          A_, {.ordering = options_.ordering, .shared_analyses = shared_analyses_});
    } catch (const NumericalError&) {
      if (options_.method != DgMethod::sipg) throw;
      // Symmetric interior penalty is coercive only above a penalty threshold, which the large
      // one-sided gradients of RK shape functions at short edges push up.
      throw NumericalError(
          "dg-sipg: the matrix is not positive definite at k_p = " +
          fmt(penalty_multiplier(options_)) +
          ": the penalty is below the coercivity threshold of the interface terms on this mesh "
          "(use --penalty auto with --kp 1 or more, or raise --kp)");
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
  const bool iterative =
      options_.method == DgMethod::augmented_lagrangian || options_.method == DgMethod::nitsche;
  double smallest_change = INFINITY;
  if (iterative && report_.iterations >= options_.max_iterations)
    report_.stop_reason = "max-iterations";
  while (iterative && report_.iterations < options_.max_iterations) {
    if (options_.method == DgMethod::augmented_lagrangian) {  // lambda <- lambda + eps [u]
      const SegmentRule& rule = gauss2_segment();
      const auto& faces = space_.interfaces();
      for (std::size_t i = 0; i < faces.size(); ++i) {
        const std::vector<int> dofs = ops_.dofs(faces[i]);
        Eigen::VectorXd uf(dofs.size());
        for (std::size_t k = 0; k < dofs.size(); ++k) uf[k] = u_[dofs[k]];
        const double step = options_.al_update_kp
                                ? penalty_multiplier(options_) * integrator_.material().E()
                                : penalty_->eps(i);
        for (int q = 0; q < 2; ++q)
          lambda_[2 * i + q] += step * (ops_.jump(faces[i], rule.t[q]) * uf);
      }
    }
    const Eigen::VectorXd next = expand(back_solve(load_ + interface_load(u_)));
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
