// The physics library's own simulation, used as a library user would: no scene, no study, no
// verification/ code (this program links vorodg::dynamics alone). A steel block meshed by core's
// generator, thrown at 1 m/s at a rigid wall chosen by its law's name, stepped with step() until
// it has bounced off:
//   - the block has left the wall with its momentum reversed: at most the impact's (the rest of
//     the energy rings in the block) and at least 95 % of it, the bounds the dynamics study's
//     wall impact holds its rebound speed to;
//   - the energy balance (kinetic + elastic - work of the wall) holds to 1e-10 of the input;
//   - the wall's law is the one named: a name not registered is refused with InputError;
//   - past the critical step the simulation reports itself unstable, and not below it.
#include <gtest/gtest.h>

#include <cmath>

#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Errors.hpp"
#include "dynamics/ExplicitSimulation.hpp"

namespace vorodg {
namespace {

const Rectangle kBlock(0.0, 0.0, 0.2, 0.05);

/// Steel, thrown along +x at a wall touching its right side, for twice the bar's round trip.
ExplicitParameters thrown_block() {
  ExplicitParameters p;
  p.bodies = {DynamicsBody{kBlock, Eigen::Vector2d(1.0, 0.0), 0.0}};
  p.E = 200e9, p.nu = 0.3, p.density = 7800.0;
  p.wall = DynamicsWall{Point(kBlock.x1(), 0.0), Point(-1.0, 0.0), 0.0, "penalty-plane"};
  p.contact = false;  // the wall only
  p.safety = 0.9;
  p.end = 4.0 * kBlock.width() / p.bar_speed();
  return p;
}

BodiesMesh block_mesh() {
  MeshSpec spec;
  spec.family = MeshFamily::quad;
  spec.domain = kBlock;
  spec.size = 0.0125;
  PolygonMesh mesh = generate_mesh(spec).mesh;
  const int cells = mesh.num_cells();
  const double h_avg = std::sqrt(kBlock.width() * kBlock.height() / cells);
  return BodiesMesh{std::move(mesh), {0, cells}, h_avg};
}

TEST(ExplicitSimulation, ALibraryUserBouncesABlockOffAWallWithoutAScene) {
  const ExplicitParameters p = thrown_block();
  const ExplicitLoading none;
  ExplicitSimulation sim(p, block_mesh(), none, /*seed=*/1, /*realization=*/0);
  const StepRecord start = sim.run->record();
  ASSERT_GT(sim.steps, 10);
  for (long s = 0; s < sim.steps; ++s) sim.step();
  const StepRecord& end = sim.run->record();
  const double balance = std::abs(end.balance() - start.balance()) / end.input_energy();
  std::printf(
      "%d cells, %ld steps of %.3e s: momentum %.6f -> %.6f kg m/s, wall work %.3e J, "
      "balance %.1e\n",
      sim.mesh().num_cells(), sim.steps, sim.dt, start.momentum.x(), end.momentum.x(),
      end.contact_work, balance);
  EXPECT_EQ(sim.contact->plane_report().contacts, 0) << "the block should have left the wall";
  const double rebound = -end.momentum.x() / start.momentum.x();
  EXPECT_GT(rebound, 0.95);
  EXPECT_LE(rebound, 1.0 + 1e-6);
  EXPECT_NEAR(end.momentum.y(), 0.0, 1e-9 * start.momentum.x());
  EXPECT_LT(balance, 1e-10);
}

/// At a step past the critical one the run's energy grows without bound: the simulation says so
/// (unstable) within a few hundred steps, its energy past kEnergyBlowUp times the input, while
/// at the stable step its kinetic plus elastic energy stays at the input over as many steps
/// (within 1 %: the wall's penalty spring holds a little of it while the block touches).
TEST(ExplicitSimulation, SaysWhenItsEnergyBlowsUp) {
  const ExplicitLoading none;
  ExplicitParameters p = thrown_block();
  p.contact = true;  // a wall and surfaces: the growth shows either way
  ExplicitSimulation stable(p, block_mesh(), none, 1, 0);
  p.safety = 1.5;
  ExplicitSimulation blowing(p, block_mesh(), none, 1, 0);
  long step = 0;
  for (; step < 2000 && !blowing.unstable(); ++step) blowing.step();
  ASSERT_TRUE(blowing.unstable()) << "no blow-up in 2000 steps at 1.5 x the critical step";
  EXPECT_TRUE(!std::isfinite(blowing.energy_growth()) || blowing.energy_growth() > kEnergyBlowUp);
  for (long s = 0; s < step; ++s) stable.step();
  EXPECT_FALSE(stable.unstable());
  EXPECT_NEAR(stable.energy_growth(), 1.0, 1e-2);
}

TEST(ExplicitSimulation, RefusesAWallLawThatIsNotRegistered) {
  ExplicitParameters p = thrown_block();
  p.wall->law = "no-such-law";
  const ExplicitLoading none;
  EXPECT_THROW(ExplicitSimulation(p, block_mesh(), none, 1, 0), InputError);
}

}  // namespace
}  // namespace vorodg
