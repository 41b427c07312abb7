#pragma once
// One solve of one problem on one mesh, stage by stage (element layer, assembly, factorization,
// solve, errors), with the wall time of each: what `vorodg solve` runs once and a study runs
// for every (level, realization, formulation, knob).
#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/element/ElementTable.hpp"
#include "core/material/IsotropicElasticity.hpp"
#include "core/mesh/PolygonMesh.hpp"
#include "core/problem/ExactSolution.hpp"
#include "core/solve/AmgConjugateGradient.hpp"
#include "core/solve/LinearSolverChoice.hpp"
#include "core/util/Stopwatch.hpp"
#include "dg/DgElasticity.hpp"
#include "verification/model/Choices.hpp"
#include "verification/solve/SharedMeshWork.hpp"

namespace vorodg {

struct SolveSettings {
  std::string problem = "beam";    // beam | patch | patch-mixed | patch-traction | mms
  std::string formulation = "cg";  // cg, or a DG formulation's name (formulation_choices)
  PlaneModel plane = PlaneModel::stress;
  double E = 1.0;
  double nu = 0.3;
  double load = 1.0;  // beam end load P
  bool mean_dilation = false;
  ElementOptions element;      // rule, correction, weight refinement/degree, threads
  LinearSolverOptions solver;  // CG: cholmod (its ordering; DG too) or amg-cg (its tolerance)
  bool errors = true;          // integrate the error against the exact solution on its own points
  bool energy_error = true;
  DgOptions dg;  // penalty scaling and k_p, tolerance, iterations, variants
};

/// cg and every registered DG formulation (dg/DgFormulation.hpp), with their docs.
const Choices& formulation_choices();
/// How the DG penalty is scaled, and which stress of a cell the DG interface terms take.
const Choices& penalty_choices();
const Choices& traction_choices();
PenaltyScaling parse_penalty(const std::string& name);
std::string penalty_name(PenaltyScaling scaling);
TractionKind parse_traction(const std::string& name);
std::string traction_name(TractionKind kind);

/// The DG options of a DG formulation's settings (formulation and ordering filled in); for cg,
/// those of dg-penalty, so that the DG settings still read back.
DgOptions dg_options(const SolveSettings& settings);

struct SolveResult {
  int dofs = 0, free_dofs = 0;
  bool errors_measured = false;               // settings.errors: the two errors below
  double l2_error = 0.0, energy_error = 0.0;  // relative
  double rcond = 0.0;                         // CHOLMOD's reciprocal condition estimate
  long factor_nonzeros = 0;  // entries of the Cholesky factor (its memory: 8 bytes each)
  LinearSolverKind solver = LinearSolverKind::cholmod;  // what the CG solve used (DG: cholmod)
  AmgCgReport amg;                                      // amg-cg: iterations and residual
  double max_divergence_defect = 0.0;  // before correction, relative to sqrt(cell area)
  double min_moment_rcond = 0.0;
  StageTimes seconds;
  std::vector<std::string> shared_stages;  // made once for the mesh (SharedMeshWork)
  Eigen::Matrix2Xd vertex_displacement;    // CG: per vertex; DG: the first cell's copy
  std::vector<int> cell_offsets;           // per cell, into cell_dof_values (2 per vertex copy)
  Eigen::VectorXd cell_dof_values;         // every cell's own displacement DOFs
  std::vector<double> edge_gaps;           // DG: largest |[u]| on each edge (0 for CG)
  std::optional<DgReport> dg;              // DG only: iterations, stop reason, gap
  std::vector<Eigen::Vector3d> cell_mean_stress;
  std::vector<double> cell_l2_density, cell_energy_density;  // empty without errors
};

/// The exact solution a problem name stands for, on `domain` (the beam needs [0,L]x[-D/2,D/2]).
/// Throws InputError for an unknown name or a domain the problem cannot live on.
std::unique_ptr<ExactSolution> make_problem(const SolveSettings& settings, const Rectangle& domain);

/// The CG solver options of a solve: the settings', except that a patch test asks for exactness
/// to round-off, which a factor gives and a tolerance does not, so there `auto` means cholmod.
LinearSolverOptions cg_solver(const SolveSettings& settings);

/// Builds the element table, assembles, solves and (with settings.errors) measures the errors;
/// the cell mean stresses come either way. With `shared`, the
/// element table and the factorization's symbolic analysis come from (or go to) the work shared
/// by the runs on `mesh`; the results are the same either way.
SolveResult run_solve(const PolygonMesh& mesh, const SolveSettings& settings,
                      SharedMeshWork* shared = nullptr);

/// A DG iteration that did not converge leaves a plausible-looking wrong answer: throws
/// NumericalError saying so (how it stopped, after how many iterations) unless it converged.
void require_converged(const SolveResult& result, const SolveSettings& settings);

}  // namespace vorodg
