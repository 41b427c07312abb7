// A block on a rigid plane under gravity tilted by theta (the plane y = 0, gravity
// g (sin theta, -cos theta): a slope), with Coulomb friction mu on the plane, in the integrator:
//   - tan theta < mu: it sticks. Once the normal force has built up (the block starts touching
//     the plane unloaded, and slips a little while it loads), its centre of mass moves less than
//     1e-4 of the distance it would slide frictionless over the second half of the run;
//   - tan theta > mu: it slides with Coulomb's acceleration g (sin theta - mu cos theta), to
//     1e-4 (measured 5e-6: the normal force rings about M g cos theta with the block's elastic
//     waves), and the slip work is mu M g cos theta times the distance slid, to 1e-3 (measured
//     7e-4: the slip of the bottom vertices is the centre's plus the block's elastic shear);
//   - in both the energy balance with the contact work closes to round-off.
// The plane's velocity penalty is the report's plastic one, so the block settles onto the
// plane instead of bouncing on its penalty spring.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dynamics/ContactForces.hpp"
#include "support/DynamicsModel.hpp"

namespace vorodg {
namespace {

using testing::DynamicsModel;
using testing::mesh_spec;

constexpr double kGravity = 9.81, kTheta = std::numbers::pi / 6;  // tan = 0.577
constexpr double kDuration = 0.1;

struct Slide {
  double distance = 0.0;       // of the centre of mass along the slope
  double late_distance = 0.0;  // the same over the second half of the run
  double acceleration = 0.0;   // from its velocity over the second half of the run
  double friction_work = 0.0;
  double balance_error = 0.0;  // of the input energy
  double normal_force = 0.0;   // M g cos theta
};

Slide slide(double mu) {
  const DynamicsModel model(mesh_spec(MeshFamily::quad, Rectangle(0, 0, 0.2, 0.1), 0.025),
                            IsotropicElasticity(1e7, 0.25, PlaneModel::strain), 1000.0);
  const double dt = model.limit.step();
  auto run = model.integrator_with(dt);
  PenaltyParameters penalty;
  penalty.plastic = true;
  ContactForces contact(model.mesh, PenaltyContact(penalty), false);
  contact.add_plane(Point(0, 0), Point(0, 1), ContactFriction(mu));
  run->set_contact(contact);
  const Eigen::Vector2d g = kGravity * Eigen::Vector2d(std::sin(kTheta), -std::cos(kTheta));
  run->set_body_force([g](double) { return g; });
  const int n = run->dofs().num_dofs();
  run->initialize(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n));
  const double M = model.mass.total();
  auto centre = [&](const Eigen::VectorXd& field) {
    double sum = 0.0;
    for (int i = 0; i < run->dofs().num_nodes(); ++i) sum += run->node_masses()[i] * field[2 * i];
    return sum / M;
  };
  const long steps = std::lround(kDuration / dt);
  double v_half = 0.0, x_half = 0.0;
  for (long s = 1; s <= steps; ++s) {
    run->step();
    if (s != steps / 2) continue;
    v_half = centre(run->velocity());
    x_half = centre(run->displacement());
  }
  Slide out;
  out.distance = centre(run->displacement());
  out.late_distance = out.distance - x_half;
  out.acceleration = (centre(run->velocity()) - v_half) / (run->time() - (steps / 2) * dt);
  out.friction_work = contact.friction_dissipated();
  const StepRecord& r = run->record();
  out.balance_error = std::abs(r.balance() - r.initial_balance) / r.input_energy();
  out.normal_force = M * kGravity * std::cos(kTheta);
  return out;
}

TEST(SlidingBlock, SticksBelowMuNAndSlidesAtCoulombsAcceleration) {
  const double free_distance = 0.5 * kGravity * std::sin(kTheta) * kDuration * kDuration;
  const Slide stuck = slide(0.8);
  std::printf(
      "stick (mu 0.8): distance %.3e (second half %.3e) of frictionless %.3e; slip work "
      "%.3e; balance %.1e\n",
      stuck.distance, stuck.late_distance, free_distance, stuck.friction_work, stuck.balance_error);
  EXPECT_LT(std::abs(stuck.late_distance), 1e-4 * free_distance);
  EXPECT_LT(stuck.balance_error, 1e-10);

  const double mu = 0.3;
  const Slide slid = slide(mu);
  const double coulomb = kGravity * (std::sin(kTheta) - mu * std::cos(kTheta));
  const double work = mu * slid.normal_force * slid.distance;
  std::printf(
      "slide (mu 0.3): acceleration %.6f, Coulomb %.6f; slip work %.6e, mu N s %.6e; "
      "balance %.1e\n",
      slid.acceleration, coulomb, slid.friction_work, work, slid.balance_error);
  EXPECT_NEAR(slid.acceleration, coulomb, 1e-4 * coulomb);
  EXPECT_NEAR(slid.friction_work, work, 1e-3 * work);
  EXPECT_LT(slid.balance_error, 1e-10);
}

}  // namespace
}  // namespace vorodg
