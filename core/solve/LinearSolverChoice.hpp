#pragma once
// Which linear solver a CG elasticity system gets: CHOLMOD's sparse Cholesky (exact to
// round-off; memory grows like the factor, docs/solvers.md) or conjugate gradients
// with hypre's AMG (memory like the matrix; stops at a tolerance), or the one the size calls for.
#include "core/solve/SparseCholesky.hpp"

namespace vorodg {

enum class LinearSolverKind {
  automatic,  // cholmod up to kAmgFromFreeDofs free DOFs, amg-cg from there (where available)
  cholmod,
  amg_cg,
};

/// From this many free DOFs on, `automatic` chooses amg-cg. On the rcp beam, one thread
/// (docs/solvers.md), CHOLMOD is 28 % faster at 1.2e6 DOFs and as fast at 3.7e6, where amg-cg
/// peaks at a quarter less memory; below 2e6 the exactness of a factor is kept, so every shipped
/// scene solves as it did before amg-cg existed.
inline constexpr int kAmgFromFreeDofs = 2'000'000;

struct LinearSolverOptions {
  LinearSolverKind kind = LinearSolverKind::automatic;
  FillOrdering ordering = FillOrdering::automatic;  // cholmod
  /// amg-cg: the stopping tolerance (AmgCgOptions::tolerance); 0 ties it to the mesh, see
  /// amg_tolerance_for().
  double amg_tolerance = 0.0;
};

/// The solver `options.kind` stands for on a system of `free_dofs` unknowns.
LinearSolverKind resolve_solver(LinearSolverKind kind, long free_dofs);

/// The amg-cg tolerance tied to the discretization: the L2 error of a linearly complete element
/// falls like (h/L)^2, and the algebraic error CG leaves, relative, is about its tolerance in
/// the energy norm (an AMG-preconditioned operator is well conditioned). A hundredth of
/// (h_avg/L)^2 keeps the algebraic part below a hundredth of the discretization error with room
/// for the constant; clamped to [1e-12, 1e-6]. L is the larger side of the domain.
double amg_tolerance_for(double h_avg, double length);

}  // namespace vorodg
