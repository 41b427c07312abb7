// A solve that skips the errors (`vorodg solve --no-errors`, SolveSettings::errors = false):
// 1. gives the same DOFs and cell mean stresses, bit for bit, as one that measures them, for
//    cg and dg-nitsche;
// 2. runs neither the error integration nor the rebuild of the weight functions after the
//    factorization (no "error" or "error_weights" stage) and leaves the error densities empty;
// 3. writes a record without error keys, which reads back as not measured, while a measured
//    record keeps its errors through the round trip.
// 4. Stage times are disjoint: they add up to no more than the wall time of the whole solve.
#include <gtest/gtest.h>

#include <string>

#include "core/util/Stopwatch.hpp"
#include "support/ElementTestMeshes.hpp"
#include "verification/solve/RunRecord.hpp"
#include "verification/solve/SolveRun.hpp"

namespace vorodg {
namespace {

using testing::make_mesh;

class SolveWithoutErrors : public ::testing::TestWithParam<const char*> {};

TEST_P(SolveWithoutErrors, SameSolutionNoErrorStagesNoErrorKeys) {
  const PolygonMesh mesh =
      make_mesh(MeshFamily::rcp, Rectangle(0.0, -0.5, 4.0, 0.5), 0.2, /*seed=*/7);
  SolveSettings s;
  s.problem = "beam";
  s.formulation = GetParam();
  const SolveResult measured = run_solve(mesh, s);
  s.errors = false;
  Stopwatch wall;
  const SolveResult skipped = run_solve(mesh, s);
  const double wall_seconds = wall.seconds();

  ASSERT_GT(measured.free_dofs, 100);
  EXPECT_TRUE((measured.cell_dof_values.array() == skipped.cell_dof_values.array()).all());
  EXPECT_EQ(measured.cell_mean_stress, skipped.cell_mean_stress);
  EXPECT_EQ(measured.rcond, skipped.rcond);

  EXPECT_TRUE(measured.errors_measured);
  EXPECT_GT(measured.l2_error, 0.0);
  EXPECT_TRUE(measured.seconds.contains("error"));
  EXPECT_FALSE(skipped.errors_measured);
  EXPECT_FALSE(skipped.seconds.contains("error"));
  EXPECT_FALSE(skipped.seconds.contains("error_weights"));
  EXPECT_TRUE(skipped.cell_l2_density.empty());
  EXPECT_TRUE(skipped.cell_energy_density.empty());

  const nlohmann::json with = to_json(run_metrics(mesh, measured));
  const nlohmann::json without = to_json(run_metrics(mesh, skipped));
  EXPECT_TRUE(with.contains("l2_error"));
  EXPECT_FALSE(without.contains("l2_error"));
  EXPECT_FALSE(without.contains("energy_error"));
  const RunMetrics back = metrics_from_json(without);
  EXPECT_FALSE(back.errors_measured);
  const RunMetrics back_measured = metrics_from_json(with);
  EXPECT_TRUE(back_measured.errors_measured);
  EXPECT_EQ(back_measured.l2_error, measured.l2_error);
  EXPECT_EQ(back_measured.energy_error, measured.energy_error);

  double stages = 0.0;
  for (const auto& [stage, seconds] : skipped.seconds) stages += seconds;
  EXPECT_LE(stages, wall_seconds) << "stage times overlap";
}

INSTANTIATE_TEST_SUITE_P(Formulations, SolveWithoutErrors, ::testing::Values("cg", "dg-nitsche"));

}  // namespace
}  // namespace vorodg
