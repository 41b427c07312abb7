// A DG formulation added from outside the library, in this file alone, with one registration
// line: incomplete interior penalty (IIPG, after Dawson, Sun and Wheeler 2004),
//   a(u, v) - int {sigma(u)} n.[v] + eps int [u].[v] = l(v),
// which keeps the consistency term and drops the symmetry term, so its matrix is not symmetric
// and one solve suffices. Being consistent, it passes the patch test, which dg-penalty (the
// penalty alone) does not; the seam must carry it end to end:
//   1. the registry knows it after the shipped four, and the solve settings list and accept it;
//   2. run_solve on the patch problem reproduces the affine field to round-off (relative L2
//      error below 1e-9) with one direct solve, where dg-penalty misses it by more than 1e-6;
//   3. on the beam, its L2 error is within 10% of dg-sipg's at the same penalty (both
//      consistent interior-penalty schemes of the same order).
#include <gtest/gtest.h>

#include <string>

#include "core/util/Errors.hpp"
#include "dg/DgFormulation.hpp"
#include "support/ElementTestMeshes.hpp"
#include "verification/solve/SettingsSchema.hpp"
#include "verification/solve/SolveRun.hpp"

namespace vorodg {
namespace {

class IncompleteInteriorPenalty final : public DgFormulation {
 public:
  PenaltyScaling default_scaling() const override { return PenaltyScaling::h_avg; }
  bool symmetric() const override { return false; }
  /// -int {sigma(u)} n.[v], beside the penalty block.
  void add_interface_block(const DgTermContext& context, std::size_t i,
                           Eigen::MatrixXd& local) const override {
    local -= context.consistency_block(i);
  }
};

// The one registration line.
const bool kRegistered = register_dg_formulation(
    {"dg-iipg", "DG, incomplete interior penalty (a test's toy)",
     [](const DgOptions&) { return std::make_unique<IncompleteInteriorPenalty>(); }});

SolveSettings settings(const std::string& problem, const std::string& formulation) {
  SolveSettings s;
  s.problem = problem;
  s.formulation = formulation;
  s.dg.penalty = PenaltyScaling::h_avg;
  s.dg.kp = 1e2;
  return s;
}

TEST(DgFormulationSeam, ARegisteredFormulationIsKnownToTheRegistryAndTheSettings) {
  ASSERT_TRUE(kRegistered);
  EXPECT_EQ(dg_formulations().back().name, "dg-iipg");
  EXPECT_TRUE(is_choice(formulation_choices(), "dg-iipg"));
  EXPECT_FALSE(check_settings(settings("patch", "dg-iipg")).has_value());
  EXPECT_THROW(register_dg_formulation({"dg-iipg", "again", nullptr}), InputError);
}

TEST(DgFormulationSeam, AToyFormulationPassesThePatchTestEndToEnd) {
  const PolygonMesh mesh =
      testing::make_mesh(MeshFamily::rcp, Rectangle(0.0, 0.0, 1.0, 1.0), 0.1, /*seed=*/5);
  const SolveResult toy = run_solve(mesh, settings("patch", "dg-iipg"));
  const SolveResult penalty = run_solve(mesh, settings("patch", "dg-penalty"));
  std::printf("patch test on %d cells: dg-iipg L2 %.2e, dg-penalty L2 %.2e\n", mesh.num_cells(),
              toy.l2_error, penalty.l2_error);
  ASSERT_TRUE(toy.dg.has_value());
  EXPECT_EQ(toy.dg->stop_reason, "direct");
  EXPECT_LT(toy.l2_error, 1e-9);
  EXPECT_GT(penalty.l2_error, 1e-6);
}

TEST(DgFormulationSeam, AToyFormulationConvergesLikeItsSymmetricSibling) {
  const PolygonMesh mesh =
      testing::make_mesh(MeshFamily::rcp, Rectangle(0.0, -0.5, 4.0, 0.5), 0.2, /*seed=*/7);
  SolveSettings sipg = settings("beam", "dg-sipg");
  sipg.dg.traction = TractionKind::mean;  // the toy's default, so only the terms differ
  const SolveResult toy = run_solve(mesh, settings("beam", "dg-iipg"));
  const SolveResult symmetric = run_solve(mesh, sipg);
  std::printf("beam: dg-iipg L2 %.4e, dg-sipg L2 %.4e\n", toy.l2_error, symmetric.l2_error);
  EXPECT_NEAR(toy.l2_error / symmetric.l2_error, 1.0, 0.1);
}

}  // namespace
}  // namespace vorodg
