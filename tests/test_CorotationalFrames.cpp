// Corotational cell kinematics (dynamics/CorotationalFrames, InternalForce with corotational =
// true), on an rcp and a hex body:
//   - a rigid turn of the whole body by 1 rad (u = (R - I)(X - X0)) gives zero force and energy,
//     to 1e-12 of the force and energy a unit strain would give;
//   - a turn by 1 rad of a homogeneous strain E (x = R (I + E) X) has the energy of the strain
//     alone (the linear 1/2 u.K u with u = E X), to 1e-12;
//   - the force is the energy's exact gradient: central differences of the energy agree to 1e-6
//     at a turned, strained and randomly perturbed state;
//   - for small displacements the force is K u up to second order: at |u| ~ 1e-6 of the cell
//     size they differ by less than 1e-4 of |K u|;
//   - the insertion check's cell stresses from the force's local displacements are those it
//     computes by turning every cell itself, to the bit;
//   - a free body spun through 6 rad by central differences keeps its size to 1 %, its energy
//     balance to 1e-4 of its kinetic energy, and its linear and angular momentum to round-off.
#include <gtest/gtest.h>

#include <cmath>

#include "dynamics/CrackInsertion.hpp"
#include "dynamics/InternalForce.hpp"
#include "support/DynamicsModel.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;

class CorotationalFrames : public ::testing::TestWithParam<MeshFamily> {
 protected:
  DynamicsModel model{mesh_spec(GetParam(), Rectangle(0, 0, 1, 0.5), 0.1),
                      IsotropicElasticity(1.0, 0.3, PlaneModel::stress), 1.0};
  SplitDofMap dofs = SplitDofMap::continuous(model.mesh);

  /// Node displacements of x = A (X - X0) + X0, i.e. u = (A - I)(X - X0).
  Eigen::VectorXd affine(const Eigen::Matrix2d& a) const {
    const Point origin(0.3, 0.2);
    Eigen::VectorXd u(2 * dofs.num_nodes());
    for (int c = 0; c < model.mesh.num_cells(); ++c)
      for (int k = 0; k < model.mesh.cell_size(c); ++k) {
        const Point x = model.mesh.vertex(model.mesh.cell_vertices(c)[k]) - origin;
        u.segment<2>(2 * dofs.node(c, k)) = (a - Eigen::Matrix2d::Identity()) * x;
      }
    return u;
  }
  static Eigen::Matrix2d turn(double theta) {
    Eigen::Matrix2d r;
    r << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
    return r;
  }
  double energy(InternalForce& force, const Eigen::VectorXd& u, Eigen::VectorXd* f = nullptr) {
    Eigen::VectorXd scratch;
    return force.compute(dofs, u, f ? *f : scratch, 1);
  }
};

TEST_P(CorotationalFrames, RigidTurnAndTurnedStrain) {
  InternalForce rotating(model.mesh, model.matrices, true), linear(model.mesh, model.matrices);
  Eigen::Matrix2d strain;
  strain << 1e-3, 4e-4, 4e-4, -2e-3;
  Eigen::VectorXd f_strain;
  const double e_strain = energy(linear, affine(Eigen::Matrix2d::Identity() + strain), &f_strain);
  Eigen::VectorXd f;
  const double e_rigid = energy(rotating, affine(turn(1.0)), &f);
  EXPECT_LT(std::abs(e_rigid), 1e-12 * e_strain / 1e-6);  // a unit strain's energy scale
  EXPECT_LT(f.norm(), 1e-12 * f_strain.norm() / 1e-3);
  const double e_turned =
      energy(rotating, affine(turn(1.0) * (Eigen::Matrix2d::Identity() + strain)));
  EXPECT_NEAR(e_turned, e_strain, 1e-12 * e_strain / 1e-3);
}

TEST_P(CorotationalFrames, ForceIsTheEnergysGradient) {
  InternalForce rotating(model.mesh, model.matrices, true);
  Eigen::Matrix2d strain;
  strain << 2e-3, -1e-3, -1e-3, 1e-3;
  Eigen::VectorXd u = affine(turn(0.7) * (Eigen::Matrix2d::Identity() + strain));
  Random random(9);
  for (int i = 0; i < u.size(); ++i) u[i] += 1e-3 * random.uniform(-1.0, 1.0);
  Eigen::VectorXd f;
  energy(rotating, u, &f);
  const double h = 1e-7;
  double worst = 0.0;
  for (int i = 0; i < u.size(); i += 7) {  // every seventh DOF
    Eigen::VectorXd up = u, down = u;
    up[i] += h, down[i] -= h;
    const double numeric = (energy(rotating, up) - energy(rotating, down)) / (2 * h);
    worst = std::max(worst, std::abs(numeric - f[i]));
  }
  EXPECT_LT(worst, 1e-6 * f.cwiseAbs().maxCoeff());
}

TEST_P(CorotationalFrames, TheChecksStressesReadTheForcesLocalDisplacements) {
  InternalForce rotating(model.mesh, model.matrices, true);
  Eigen::Matrix2d strain;
  strain << 2e-3, -1e-3, -1e-3, 1e-3;
  Eigen::VectorXd u = affine(turn(2.5) * (Eigen::Matrix2d::Identity() + strain));
  u += random_vector(int(u.size()), 1e-3, 11);
  energy(rotating, u);
  CrackInsertion check(model.mesh, model.integrator, MohrCoulomb({1.0, 0.5, 1.0}),
                       std::vector<char>(model.mesh.num_edges(), 1));
  check.turn_with(rotating.frames());
  const Eigen::Matrix3Xd turned_here = check.cell_stresses(dofs, u, 1);
  const Eigen::Matrix3Xd read = check.cell_stresses(dofs, u, 1, rotating.local_displacements());
  EXPECT_EQ(read, turned_here);
  EXPECT_GT(read.cwiseAbs().maxCoeff(), 1e-4);  // strained: not trivially zero
}

TEST_P(CorotationalFrames, SmallDisplacementsGiveKu) {
  InternalForce rotating(model.mesh, model.matrices, true), linear(model.mesh, model.matrices);
  Random random(3);
  Eigen::VectorXd u(2 * dofs.num_nodes());
  for (int i = 0; i < u.size(); ++i) u[i] = 1e-7 * random.uniform(-1.0, 1.0);
  Eigen::VectorXd f, ku;
  energy(rotating, u, &f);
  energy(linear, u, &ku);
  EXPECT_LT((f - ku).norm(), 1e-4 * ku.norm());
}

TEST_P(CorotationalFrames, ASpinningBodyKeepsItsShape) {
  // Spun through 10 rad over 2000 steps about its centre: with turning frames it keeps its size
  // (small strain would draw it sqrt(1 + 10^2) = 10 times larger), energy closes to O(dt^2) and
  // both momenta to round-off.
  const double dt = model.limit.step(), steps = 2000, omega = 10.0 / (steps * dt);
  CentralDifference run(model.mesh, model.mass, InternalForce(model.mesh, model.matrices, true),
                        dofs, dt);
  const Point centre(0.5, 0.25);
  auto radius = [&] {
    double r = 0.0;
    for (int i = 0; i < run.dofs().num_nodes(); ++i)
      r = std::max(r,
                   (run.node_position(i) + run.displacement().segment<2>(2 * i) - centre).norm());
    return r;
  };
  Eigen::VectorXd v(2 * dofs.num_nodes());
  for (int i = 0; i < dofs.num_nodes(); ++i) {
    const Point r = run.node_position(i) - centre;
    v.segment<2>(2 * i) = omega * Point(-r.y(), r.x());
  }
  run.initialize(Eigen::VectorXd::Zero(v.size()), v);
  const double r0 = radius();
  const StepRecord start = run.record();
  for (int s = 0; s < steps; ++s) run.step();
  const StepRecord& end = run.record();
  EXPECT_NEAR(radius(), r0, 0.01 * r0);
  EXPECT_LT(std::abs(end.balance() - end.initial_balance), 1e-4 * start.kinetic);
  EXPECT_LT(end.momentum.norm(), 1e-12 * model.mass.total() * omega * r0);
  EXPECT_NEAR(end.angular_momentum, start.angular_momentum,
              1e-12 * std::abs(start.angular_momentum));
}

INSTANTIATE_TEST_SUITE_P(Families, CorotationalFrames,
                         ::testing::Values(MeshFamily::rcp, MeshFamily::hex), [](const auto& info) {
                           return std::string(info.param == MeshFamily::rcp ? "rcp" : "hex");
                         });

}  // namespace
}  // namespace vorodg
