#pragma once
// Continuous Galerkin linear elasticity on the RK polygon element layer (deal.II's step-8 in
// spirit): two DOFs per mesh vertex, the shared cell-stiffness kernel, prescribed displacements
// imposed at the vertices of Dirichlet sides (the shape functions are Kronecker-delta there) and
// eliminated from the system, tractions integrated along the edges of traction sides, a body
// force over the cells, and one linear solve: CHOLMOD's supernodal Cholesky, or conjugate
// gradients with hypre's AMG for systems whose factor would not fit (core/solve/
// LinearSolverChoice).
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <optional>

#include "core/element/ElasticityIntegrator.hpp"
#include "core/element/ElementTable.hpp"
#include "core/problem/BoundaryValueProblem.hpp"
#include "core/solve/AmgConjugateGradient.hpp"
#include "core/solve/DirichletConstraints.hpp"
#include "core/solve/LinearSolverChoice.hpp"
#include "core/solve/SparseCholesky.hpp"
#include "core/util/Stopwatch.hpp"

namespace vorodg {

class CgElasticity {
 public:
  CgElasticity(const ElementTable& table, const ElasticityIntegrator& integrator,
               const BoundaryValueProblem& problem, int threads = 1,
               LinearSolverOptions solver = {});

  /// setup_system, assemble_system, solve. Throws InputError if no side carries Dirichlet data
  /// (rigid motions free), NumericalError if the factorization breaks down or CG does not
  /// converge.
  void run();

  void setup_system();
  void assemble_system();
  void solve();
  /// Shares the symbolic analysis of the factorization with other runs on the same mesh (a
  /// study's): one kept for the same pattern is used, a new one is kept. Results are unchanged.
  void share_analyses(SymbolicAnalyses* analyses) { shared_analyses_ = analyses; }

  /// Displacement of every vertex (the nodal values: shape functions are Kronecker-delta).
  const Eigen::Matrix2Xd& vertex_displacement() const { return displacement_; }
  /// The cell's DOF vector (u_x, u_y per vertex in loop order), as the integrator expects.
  Eigen::VectorXd cell_dofs(int c) const;
  int num_dofs() const { return 2 * table_.mesh().num_vertices(); }
  int num_free_dofs() const { return constraints_ ? constraints_->num_free() : 0; }
  /// The assembled system (after assemble_system): the lower triangle of the free-free block,
  /// and its right-hand side. A solve with cholmod consumes the matrix (it is empty afterwards).
  const Eigen::SparseMatrix<double>& system_matrix() const { return K_; }
  const Eigen::VectorXd& system_rhs() const { return rhs_; }
  /// The in-plane rigid rotation about the domain's centre on the free DOFs (after
  /// setup_system), scaled by the domain's size: what AMG adds to its interpolation.
  Eigen::VectorXd free_rotation_mode() const;
  /// The solver the options resolved to (known after solve()).
  LinearSolverKind solver() const { return solver_used_; }
  const FactorizationReport& factorization() const { return factorization_; }  // cholmod
  const AmgCgReport& amg_report() const { return amg_report_; }                // amg-cg
  const StageTimes& seconds() const { return seconds_; }

 private:
  void add_lifting(int c, const Eigen::Ref<const Eigen::MatrixXd>& Kc,
                   Eigen::VectorXd& lifted) const;
  Eigen::VectorXd solve_by_cholesky();
  /// The vertex of each node (DOF pair) of the free system, for the geometric ordering; empty
  /// where the free DOFs do not come in pairs.
  Eigen::Matrix2Xd free_node_points() const;
  Eigen::VectorXd solve_by_amg_cg();

  const ElementTable& table_;
  const ElasticityIntegrator& integrator_;
  const BoundaryValueProblem& problem_;
  int threads_;
  LinearSolverOptions solver_options_;
  LinearSolverKind solver_used_ = LinearSolverKind::automatic;
  SymbolicAnalyses* shared_analyses_ = nullptr;

  std::optional<DirichletConstraints> constraints_;
  Eigen::SparseMatrix<double> K_;  // lower triangle of the free-free block
  Eigen::VectorXd rhs_;            // free DOFs
  Eigen::Matrix2Xd displacement_;
  FactorizationReport factorization_;
  AmgCgReport amg_report_;
  StageTimes seconds_;
};

}  // namespace vorodg
