#pragma once
// Discontinuous Galerkin elasticity on disconnected RK polygons (report section 9; sign
// conventions and multiplier placement: docs/design.md "Discontinuous Galerkin"). The bulk term
// is the shared cell-stiffness kernel, unchanged; the formulations differ in their interface
// terms (eps per interface from InterfacePenalty, [u] = u_1 - u_2, n outward from cell 1, {.} the
// interface average, weighted or plain):
//   penalty:    a(u,v) + eps int [u].[v] = l(v)                                  (one solve)
//   al:         a(u,v) + int lambda.[v] + eps int [u].[v] = l(v),
//               lambda <- lambda + eps [u] at the interface quadrature points     (Eqs. 24-26)
//   nitsche:    a(u,v) + eps int [u].[v] = l(v) + int {sigma(u^i)} n . [v]  (Eqs. 27-29)
//   sipg:       a(u,v) - int {sigma(u)}n.[v] + s int {sigma(v)}n.[u] + eps int [u].[v] = l(v),
//               s = -1 symmetric (SIPG), +1 non-symmetric (NIPG), as MFEM's ex17 (one solve)
// Each cell's stress on an interface is its point, fan or mean stress (TractionKind).
// The iterative schemes factor a + eps P once and back-solve per iteration. Each scheme is one
// DgFormulation (dg/formulations/), chosen by name; this class knows none of them.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <optional>
#include <string>

#include "core/element/ElasticityIntegrator.hpp"
#include "core/problem/BoundaryValueProblem.hpp"
#include "core/solve/DirichletConstraints.hpp"
#include "core/solve/SparseCholesky.hpp"
#include "core/util/Stopwatch.hpp"
#include "dg/DgFormulation.hpp"
#include "interfaces/DgSpace.hpp"
#include "interfaces/InterfaceOperators.hpp"
#include "interfaces/InterfacePenalty.hpp"

namespace vorodg {

struct DgOptions {
  std::string formulation = "dg-nitsche";  // a registered DgFormulation's name
  // Unset: the method's default (penalty_scaling(), penalty_multiplier()).
  std::optional<PenaltyScaling> penalty;
  std::optional<double> kp;       // multiplier of the scaling: k_p E / h, or k_p eta_F
  bool weighted_average = false;  // coercive: average weighted by the cells' trace constants
  double tolerance = 1e-10;       // relative change of u between iterations
  int max_iterations = 500;
  bool al_update_kp = false;  // the report's Eq. 26: lambda <- lambda + kp E [u] (no 1/h)
  std::optional<TractionKind> traction;              // unset: fan for dg-sipg, mean for the others
  int sipg_sign = -1;                                // -1 symmetric, +1 non-symmetric
  FillOrdering ordering = FillOrdering::node_metis;  // of the sparse Cholesky factor
};

/// The scaling in effect: the option, else the formulation's default (coercive for dg-sipg, whose
/// symmetric interior penalty is only coercive above a mesh-dependent threshold; h-avg, the
/// report's, for the others).
PenaltyScaling penalty_scaling(const DgOptions& options);
/// k_p in effect: the option, else 1 for the coercive scaling (the proven bound), 1e3 otherwise.
double penalty_multiplier(const DgOptions& options);
/// The stress the interface terms take from each cell: the option, else the formulation's default
/// (fan for dg-sipg, own stress whose trace constant stays bounded at short edges; mean for the
/// others, Eq. 29).
TractionKind interface_traction(const DgOptions& options);

struct DgReport {
  int iterations = 0;
  std::string stop_reason;    // direct, converged, max-iterations, diverged
  double last_change = 0.0;   // relative change of the last iteration
  double gap_norm = 0.0;      // (int_interfaces |[u]|^2)^1/2
  double relative_gap = 0.0;  // gap_norm / (int_interfaces |{u}|^2)^1/2
  double penalty = 0.0;       // eps on an interface of size h_avg (median eps if coercive)
  double seconds_per_iteration = 0.0;
};

class DgElasticity {
 public:
  DgElasticity(const ElementTable& table, const ElasticityIntegrator& integrator,
               const BoundaryValueProblem& problem, const DgOptions& options, int threads = 1);

  void run();
  void setup_system();
  void assemble_system();
  void solve();
  /// Shares the symbolic analysis of the factorization with other runs on the same mesh (a
  /// study's): one kept for the same pattern is used, a new one is kept. Results are unchanged.
  void share_analyses(SymbolicAnalyses* analyses) { shared_analyses_ = analyses; }

  const DgSpace& space() const { return space_; }
  /// The cell's own DOF vector (its copies), as the integrator expects.
  Eigen::VectorXd cell_dofs(int c) const { return u_(space_.cell_dofs(c)); }
  /// Largest |[u]| over the interface quadrature points of each edge (0 on boundary edges).
  std::vector<double> edge_gaps() const;
  int num_dofs() const { return space_.num_dofs(); }
  int num_free_dofs() const { return constraints_ ? constraints_->num_free() : 0; }
  const FactorizationReport& factorization() const { return factorization_; }
  /// Whether the system is symmetric (all but non-symmetric interior penalty, NIPG).
  bool symmetric() const;
  /// The assembled matrix on the free DOFs (after assemble_system()): its lower triangle if
  /// symmetric(), else the whole matrix.
  const Eigen::SparseMatrix<double>& system_matrix() const { return A_; }
  const DgReport& report() const { return report_; }
  /// The interface penalties and weights (after assemble_system()).
  const InterfacePenalty& penalty() const { return *penalty_; }
  const StageTimes& seconds() const { return seconds_; }

 private:
  Eigen::MatrixXd interface_matrix(std::size_t interface) const;
  /// What the formulation's terms read (after assemble_system()).
  DgTermContext term_context() const;
  void measure_gap();
  double median_penalty() const;

  const ElementTable& table_;
  const ElasticityIntegrator& integrator_;
  const BoundaryValueProblem& problem_;
  DgOptions options_;
  int threads_;
  SymbolicAnalyses* shared_analyses_ = nullptr;
  DgSpace space_;
  InterfaceOperators ops_;
  std::unique_ptr<DgFormulation> formulation_;
  TractionKind traction_;  // the stress the interface terms take, resolved once
  std::unique_ptr<InterfacePenalty> penalty_;

  std::optional<DirichletConstraints> constraints_;
  Eigen::VectorXd load_, u_;
  Eigen::SparseMatrix<double> A_;        // free-free block (lower triangle if symmetric)
  Eigen::SparseMatrix<double> A_fixed_;  // free rows, prescribed columns
  FactorizationReport factorization_;
  DgReport report_;
  StageTimes seconds_;
};

}  // namespace vorodg
