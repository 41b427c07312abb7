// The amg-cg solver (core/solve/AmgConjugateGradient, its choice in core/solve/
// LinearSolverChoice and its use by CG elasticity), docs/solvers.md:
//   - on the rcp beam it gives the errors CHOLMOD gives, within 1% of themselves, at the
//     tolerance tied to the mesh, and the residual it reports is the true one;
//   - its iteration count stays nearly flat as the mesh is refined (what AMG is for);
//   - the nodal setting with the rotation mode solves the same system;
//   - results are bitwise the same for 1 and 2 assembly threads, and for solves run
//     concurrently from two threads (hypre's calls are serialized);
//   - it refuses to return an unconverged solution; `auto` picks cholmod below the crossover;
//   - with hypre linked, a large freed array still goes back to the system (SuperLU_DIST, which
//     hypre links, turns that off when it is loaded; vorodg turns it back on).
#include <gtest/gtest.h>

#include <unistd.h>

#include <Eigen/SparseCholesky>
#include <fstream>
#include <thread>

#include "cg/CgElasticity.hpp"
#include "core/element/ElasticityIntegrator.hpp"
#include "core/element/ElementTable.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/solve/AmgConjugateGradient.hpp"
#include "core/solve/LinearSolverChoice.hpp"
#include "core/util/Errors.hpp"
#include "support/ElementTestMeshes.hpp"
#include "verification/solve/SolveRun.hpp"

namespace vorodg {
namespace {

using testing::make_mesh;

const Rectangle kBeam(0.0, -0.5, 4.0, 0.5);

SolveResult solve_beam(const PolygonMesh& mesh, LinearSolverKind kind, int threads = 1,
                       double tolerance = 0.0) {
  SolveSettings s;
  s.problem = "beam";
  s.element.threads = threads;
  s.solver.kind = kind;
  s.solver.amg_tolerance = tolerance;
  return run_solve(mesh, s);
}

/// A 1D Laplacian with both ends fixed, as two uncoupled components per node (a block size of
/// 2): symmetric positive definite, condition number ~ n^2.
Eigen::SparseMatrix<double> laplacian_pairs(int nodes) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < nodes; ++i)
    for (int c = 0; c < 2; ++c) {
      t.emplace_back(2 * i + c, 2 * i + c, 2.0);
      if (i + 1 < nodes) t.emplace_back(2 * (i + 1) + c, 2 * i + c, -1.0);
    }
  Eigen::SparseMatrix<double> lower(2 * nodes, 2 * nodes);
  lower.setFromTriplets(t.begin(), t.end());
  return lower;
}

class AmgCg : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!AmgConjugateGradient::available()) GTEST_SKIP() << "built without hypre";
  }
};

TEST_F(AmgCg, GivesTheErrorsOfTheDirectSolveOnTheBeam) {
  const PolygonMesh mesh = make_mesh(MeshFamily::rcp, kBeam, 0.04, /*seed=*/11);
  const SolveResult direct = solve_beam(mesh, LinearSolverKind::cholmod);
  const SolveResult amg = solve_beam(mesh, LinearSolverKind::amg_cg);
  ASSERT_EQ(amg.solver, LinearSolverKind::amg_cg);
  EXPECT_EQ(direct.solver, LinearSolverKind::cholmod);
  EXPECT_GT(amg.amg.iterations, 0);
  EXPECT_LE(std::abs(amg.l2_error - direct.l2_error), 0.01 * direct.l2_error);
  EXPECT_LE(std::abs(amg.energy_error - direct.energy_error), 0.01 * direct.energy_error);
  // The displacements themselves agree far better than the errors need.
  const double scale = direct.cell_dof_values.cwiseAbs().maxCoeff();
  EXPECT_LE((amg.cell_dof_values - direct.cell_dof_values).cwiseAbs().maxCoeff(), 1e-4 * scale);
}

TEST_F(AmgCg, ReportsTheTrueResidualAndMeetsALooseTolerance) {
  const PolygonMesh mesh = make_mesh(MeshFamily::rcp, kBeam, 0.05, /*seed=*/4);
  const SolveResult loose = solve_beam(mesh, LinearSolverKind::amg_cg, 1, 1e-3);
  const SolveResult tight = solve_beam(mesh, LinearSolverKind::amg_cg, 1, 1e-10);
  EXPECT_LT(loose.amg.iterations, tight.amg.iterations);
  EXPECT_LT(tight.amg.relative_residual, 1e-3 * loose.amg.relative_residual);
  EXPECT_GT(loose.amg.relative_residual, 0.0);
}

// AMG's point: the iterations barely grow while the unknowns grow fourfold.
TEST_F(AmgCg, IterationsStayNearlyFlatUnderRefinement) {
  int previous = 0;
  for (double d : {0.08, 0.04, 0.02}) {
    const PolygonMesh mesh = make_mesh(MeshFamily::rcp, kBeam, d, /*seed=*/5);
    const SolveResult r = solve_beam(mesh, LinearSolverKind::amg_cg, 2, 1e-8);
    SCOPED_TRACE("d = " + std::to_string(d) + ": " + std::to_string(r.free_dofs) + " DOFs");
    EXPECT_LE(r.amg.iterations, 40);
    if (previous) {
      EXPECT_LE(r.amg.iterations, previous + 6);
    }
    previous = r.amg.iterations;
  }
}

// The nodal setting with the rotation mode (not CG elasticity's default) solves the same system.
TEST_F(AmgCg, NodalCoarseningWithTheRotationModeSolvesTheSameSystem) {
  const PolygonMesh mesh = make_mesh(MeshFamily::rcp, kBeam, 0.03, /*seed=*/8);
  SolveSettings s;
  s.problem = "beam";
  const auto problem = make_problem(s, mesh.domain());
  const ElementTable table(mesh, s.element);
  const ElasticityIntegrator integrator(table, problem->material(), false);
  CgElasticity cg(table, integrator, *problem);
  cg.setup_system();
  cg.assemble_system();
  AmgConjugateGradient with, without;
  with.setup(cg.system_matrix(), cg.free_rotation_mode(), {.tolerance = 1e-8});
  without.setup(cg.system_matrix(), Eigen::VectorXd(), {.tolerance = 1e-8});
  const Eigen::VectorXd u_with = with.solve(cg.system_rhs());
  const Eigen::VectorXd u_without = without.solve(cg.system_rhs());
  EXPECT_GT(with.report().levels, 2);
  EXPECT_GT(without.report().levels, 2);
  EXPECT_LE(with.report().iterations, 40);
  EXPECT_LE((u_with - u_without).norm(), 1e-5 * u_with.norm());
}

TEST_F(AmgCg, ThreadsAndConcurrentSolvesGiveTheSameBits) {
  const PolygonMesh mesh = make_mesh(MeshFamily::rcp, kBeam, 0.05, /*seed=*/6);
  const SolveResult one = solve_beam(mesh, LinearSolverKind::amg_cg, 1);
  const SolveResult two = solve_beam(mesh, LinearSolverKind::amg_cg, 2);
  EXPECT_TRUE((one.cell_dof_values.array() == two.cell_dof_values.array()).all());
  EXPECT_EQ(one.amg.iterations, two.amg.iterations);
  SolveResult a, b;
  std::thread first([&] { a = solve_beam(mesh, LinearSolverKind::amg_cg, 1); });
  std::thread second([&] { b = solve_beam(mesh, LinearSolverKind::amg_cg, 1); });
  first.join();
  second.join();
  EXPECT_TRUE((a.cell_dof_values.array() == one.cell_dof_values.array()).all());
  EXPECT_TRUE((b.cell_dof_values.array() == one.cell_dof_values.array()).all());
}

TEST_F(AmgCg, SolvesASmallSystemToItsTolerance) {
  const Eigen::SparseMatrix<double> lower = laplacian_pairs(200);
  const Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(lower.rows(), -1.0, 2.0);
  AmgConjugateGradient amg;
  amg.setup(lower, Eigen::VectorXd(), {.tolerance = 1e-12});
  const Eigen::VectorXd u = amg.solve(rhs);
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> ldlt(lower);
  const Eigen::VectorXd exact = ldlt.solve(rhs);
  EXPECT_LE((u - exact).norm(), 1e-8 * exact.norm());
  EXPECT_LE(amg.report().relative_residual, 1e-9);
  // A second right-hand side reuses the hierarchy.
  const Eigen::VectorXd u2 = amg.solve(2.0 * rhs);
  EXPECT_LE((u2 - 2.0 * exact).norm(), 1e-8 * exact.norm());
}

TEST_F(AmgCg, RefusesAnUnconvergedSolution) {
  const Eigen::SparseMatrix<double> lower = laplacian_pairs(400);
  const Eigen::VectorXd rhs = Eigen::VectorXd::Ones(lower.rows());
  AmgConjugateGradient amg;
  amg.setup(lower, Eigen::VectorXd(), {.tolerance = 1e-15, .max_iterations = 1});
  EXPECT_THROW(amg.solve(rhs), NumericalError);
}

TEST(LinearSolverChoice, AutomaticPicksCholmodBelowTheCrossover) {
  EXPECT_EQ(resolve_solver(LinearSolverKind::automatic, kAmgFromFreeDofs - 1),
            LinearSolverKind::cholmod);
  EXPECT_EQ(
      resolve_solver(LinearSolverKind::automatic, kAmgFromFreeDofs),
      AmgConjugateGradient::available() ? LinearSolverKind::amg_cg : LinearSolverKind::cholmod);
  EXPECT_EQ(resolve_solver(LinearSolverKind::cholmod, 1L << 40), LinearSolverKind::cholmod);
  EXPECT_EQ(resolve_solver(LinearSolverKind::amg_cg, 10), LinearSolverKind::amg_cg);
}

TEST(LinearSolverChoice, PatchTestsKeepTheFactorUnlessAskedOtherwise) {
  SolveSettings s;
  for (const char* problem : {"patch", "patch-mixed", "patch-traction"}) {
    s.problem = problem;
    s.solver.kind = LinearSolverKind::automatic;
    EXPECT_EQ(cg_solver(s).kind, LinearSolverKind::cholmod) << problem;
    s.solver.kind = LinearSolverKind::amg_cg;
    EXPECT_EQ(cg_solver(s).kind, LinearSolverKind::amg_cg) << problem;
  }
  s.problem = "beam";
  s.solver.kind = LinearSolverKind::automatic;
  EXPECT_EQ(cg_solver(s).kind, LinearSolverKind::automatic);
}

TEST(LinearSolverChoice, ToleranceFollowsTheMeshWithinItsClamps) {
  EXPECT_DOUBLE_EQ(amg_tolerance_for(0.01, 1.0), 1e-6);   // 0.01 * 1e-4 = 1e-6
  EXPECT_DOUBLE_EQ(amg_tolerance_for(0.001, 1.0), 1e-8);  // 0.01 * 1e-6
  EXPECT_DOUBLE_EQ(amg_tolerance_for(0.1, 1.0), 1e-6);    // clamped from above
  EXPECT_DOUBLE_EQ(amg_tolerance_for(1e-7, 1.0), 1e-12);  // clamped from below
  EXPECT_DOUBLE_EQ(amg_tolerance_for(0.004, 4.0), 1e-8);  // relative to the domain
}

TEST(LinearSolverChoice, WithoutHypreAmgCgIsRefusedClearly) {
  if (AmgConjugateGradient::available()) GTEST_SKIP() << "built with hypre";
  AmgConjugateGradient amg;
  EXPECT_THROW(amg.setup(laplacian_pairs(4), Eigen::VectorXd()), InputError);
}

TEST(LinearSolverChoice, DgFormulationsRefuseAmgCg) {
  const PolygonMesh mesh = make_mesh(MeshFamily::rcp, kBeam, 0.2, /*seed=*/1);
  SolveSettings s;
  s.problem = "beam";
  s.formulation = "dg-nitsche";
  s.solver.kind = LinearSolverKind::amg_cg;
  EXPECT_THROW(run_solve(mesh, s), InputError);
}

/// Resident memory of this process in KiB (/proc/self/statm counts pages).
long resident_kib() {
  std::ifstream statm("/proc/self/statm");
  long size = 0, resident = 0;
  statm >> size >> resident;
  return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

TEST(MemoryReturn, AFreedLargeArrayLeavesTheProcess) {
#ifdef VORODG_SANITIZED
  GTEST_SKIP() << "AddressSanitizer keeps freed memory in quarantine";
#endif
  const long before = resident_kib();
  {
    std::vector<double> big(std::size_t{128} << 17);  // 128 MiB, every page touched
    for (std::size_t i = 0; i < big.size(); i += 512) big[i] = 1.0;
    EXPECT_GT(resident_kib() - before, 100 * 1024);
  }
  EXPECT_LT(resident_kib() - before, 16 * 1024);
}

}  // namespace
}  // namespace vorodg
