// Coulomb friction on closed crack faces in explicit dynamics (dynamics/CohesiveForces with the
// kernel of fracture/FacePoint), on two quads sharing one cracked edge of length L. The face is
// broken first (opened past the critical opening, so the law carries nothing), then closed by
// delta and sheared monotonically to S, one cell moving rigidly against the other:
//   - it sticks while the shear is below mu p (p = k delta, k the closure stiffness): the shear
//     force is k s L, nothing is dissipated;
//   - it slips beyond: the shear force is mu p L, and the energy dissipated is
//     mu p L (S - mu delta), Coulomb's slip work, to 1e-12 relative;
//   - the work the forces booked over the shear equals what friction dissipated plus what its
//     stick spring stores, to 1e-10 relative (the transition falls on a step; round-off of 400
//     steps of booking);
//   - under a pressure that varies while the face slips, back and forth, and as it opens again,
//     the booked work still equals dissipated plus stored to 1e-12 relative: the dissipation
//     is the trapezoid of the shear over the slip (Coulomb's at constant pressure);
//   - without friction (mu = 0) a closed face carries no shear and stores no friction energy;
//   - a negative or non-finite mu is refused.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "core/util/Errors.hpp"
#include "dynamics/CohesiveForces.hpp"
#include "support/DynamicsModel.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;

constexpr double kE = 30e9, kH = 0.01;

struct Pair {
  DynamicsModel model{mesh_spec(MeshFamily::quad, Rectangle(0, 0, 2 * kH, kH), kH),
                      IsotropicElasticity(kE, 0.2, PlaneModel::strain), 2400.0};
  CohesiveLaw law{CohesiveParameters{3e6, 50.0, 1.0, "linear", 10 * kE / kH}};
  int edge = -1;
  Eigen::Vector2d n, t;
  double length = 0.0;

  Pair() {
    for (int e = 0; e < model.mesh.num_edges(); ++e)
      if (!model.mesh.edge(e).on_boundary()) edge = e;
    const MeshEdge& me = model.mesh.edge(edge);
    const Eigen::Vector2d d = model.mesh.vertex(me.v1) - model.mesh.vertex(me.v0);
    length = d.norm();
    t = d / length;
    n = Eigen::Vector2d(t.y(), -t.x());
  }
  /// Cell1 moved rigidly by the opening (gn, gt) against cell0, on a map split at the edge.
  Eigen::VectorXd displacement(const SplitDofMap& dofs, double gn, double gt) const {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(dofs.num_dofs());
    const int cell1 = model.mesh.edge(edge).cell1;
    for (int k = 0; k < model.mesh.cell_size(cell1); ++k)
      u.segment<2>(2 * dofs.node(cell1, k)) = gn * n + gt * t;
    return u;
  }
  /// The shear force on cell1 (along t) at the last evaluation.
  double shear_force(const SplitDofMap& dofs, const Eigen::VectorXd& f) const {
    const int cell1 = model.mesh.edge(edge).cell1;
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    for (int k = 0; k < model.mesh.cell_size(cell1); ++k)
      sum += f.segment<2>(2 * dofs.node(cell1, k));
    return -sum.dot(t);  // the force resists the slide
  }
};

struct ShearRun {
  double stick_force = 0.0, slip_force = 0.0, work = 0.0, dissipated = 0.0, stored = 0.0;
};

/// The map split at the pair's edge.
std::vector<char> split_at(const Pair& p) {
  std::vector<char> connected(p.model.mesh.num_edges(), 1);
  connected[p.edge] = 0;
  return connected;
}

/// The pair's edge cracked with friction mu and opened past the critical opening: broken, so
/// the law carries nothing and only friction and the closure act.
struct BrokenFace {
  CohesiveForces faces;
  SplitDofMap dofs;
  Eigen::VectorXd f;
  BrokenFace(const Pair& p, double mu)
      : faces(p.model.mesh, p.law), dofs(p.model.mesh, split_at(p)) {
    faces.set_friction(mu);
    faces.add_edge(p.edge);
    faces.bind(dofs);
    f = Eigen::VectorXd::Zero(dofs.num_dofs());
    faces.evaluate(p.displacement(dofs, 3.0 * p.law.critical_opening(), 0.0), f);
    EXPECT_TRUE(faces.broken(p.edge));
  }
};

ShearRun shear(Pair& p, double mu, double delta, double total, int steps, int stick_steps) {
  BrokenFace broken(p, mu);
  CohesiveForces& faces = broken.faces;
  const SplitDofMap& dofs = broken.dofs;
  Eigen::VectorXd& f = broken.f;
  f.setZero();
  faces.evaluate(p.displacement(dofs, -delta, 0.0), f);  // closed, not yet sheared
  ShearRun r;
  const double before = faces.work(), stored_before = faces.stored_energy();
  for (int i = 1; i <= steps; ++i) {
    f.setZero();
    faces.evaluate(p.displacement(dofs, -delta, total * i / steps), f);
    if (i == stick_steps / 2) r.stick_force = p.shear_force(dofs, f);
  }
  r.slip_force = p.shear_force(dofs, f);
  r.work = -(faces.work() - before);
  r.dissipated = faces.friction_dissipated_energy();
  r.stored = faces.stored_energy() - stored_before;
  return r;
}

TEST(CohesiveFriction, SticksThenSlipsWithCoulombsWork) {
  Pair p;
  const double mu = 0.6, k = 0.1 * p.law.parameters().initial_stiffness;
  const double delta = 1e-7, pressure = k * delta, stick = mu * delta;
  const int steps = 400, stick_steps = 40;  // the shear reaches mu delta at step 40
  const double total = stick * steps / stick_steps;
  const ShearRun r = shear(p, mu, delta, total, steps, stick_steps);
  EXPECT_NEAR(r.stick_force, k * (stick / 2) * p.length, 1e-12 * k * stick * p.length);
  EXPECT_NEAR(r.slip_force, mu * pressure * p.length, 1e-12 * mu * pressure * p.length);
  const double coulomb = mu * pressure * p.length * (total - stick);
  EXPECT_NEAR(r.dissipated, coulomb, 1e-12 * coulomb);
  EXPECT_NEAR(r.work, r.dissipated + r.stored, 1e-10 * r.work);
}

TEST(CohesiveFriction, UnderAVaryingPressureTheWorkIsDissipatedPlusStored) {
  Pair p;
  BrokenFace broken(p, 0.6);
  CohesiveForces& faces = broken.faces;
  const SplitDofMap& dofs = broken.dofs;
  Eigen::VectorXd& f = broken.f;
  const double delta = 1e-7;
  const auto at = [&](int i, int steps) {  // closed, slides 5 mu delta and back; open at the end
    const double s = double(i) / steps;
    const double gn = i == steps ? 0.0 : -delta * (1.0 + 0.8 * std::sin(17.0 * s));
    f.setZero();
    faces.evaluate(p.displacement(dofs, gn, 3.0 * delta * std::sin(6.0 * s)), f);
  };
  const int steps = 600;
  at(0, steps);
  const double before = faces.work(), stored_before = faces.stored_energy();
  for (int i = 1; i <= steps; ++i) at(i, steps);
  const double work = -(faces.work() - before), dissipated = faces.friction_dissipated_energy();
  EXPECT_GT(dissipated, 0.1 * work);      // it slipped
  EXPECT_EQ(faces.stored_energy(), 0.0);  // open again: no spring, no closure
  EXPECT_NEAR(work + stored_before, dissipated, 1e-12 * work);
}

TEST(CohesiveFriction, WithoutFrictionAClosedFaceCarriesNoShear) {
  Pair p;
  const ShearRun r = shear(p, 0.0, 1e-7, 6e-7, 40, 4);
  EXPECT_EQ(r.slip_force, 0.0);
  EXPECT_EQ(r.dissipated, 0.0);
  EXPECT_EQ(r.work, 0.0);
}

TEST(CohesiveFriction, ATurnedFaceReadsItsOpeningInItsOwnFrame) {
  // Both cells turned rigidly by theta about the origin, cell1 pressed into cell0 by delta along
  // the turned normal: with turning frames the face carries the closure's k delta L along R n
  // and no shear, at any theta; in the reference frame it would read a shear of k delta sin.
  Pair p;
  const double k = 0.1 * p.law.parameters().initial_stiffness, delta = 1e-7;
  const SplitDofMap dofs(p.model.mesh, split_at(p));
  const int cell1 = p.model.mesh.edge(p.edge).cell1;
  for (const double theta : {0.3, 2.0, 10.0}) {
    const Eigen::Matrix2d R = Eigen::Rotation2Dd(theta).toRotationMatrix();
    Eigen::VectorXd u(dofs.num_dofs());
    for (int c = 0; c < p.model.mesh.num_cells(); ++c)
      for (int j = 0; j < p.model.mesh.cell_size(c); ++j) {
        const Point X = p.model.mesh.vertex(p.model.mesh.cell_vertices(c)[j]);
        const Point x = R * (c == cell1 ? Point(X - delta * p.n) : X);
        u.segment<2>(2 * dofs.node(c, j)) = x - X;
      }
    for (const bool turning : {true, false}) {
      CohesiveForces faces(p.model.mesh, p.law);
      faces.set_turning_frames(turning);
      faces.add_edge(p.edge);
      faces.bind(dofs);
      Eigen::VectorXd f = Eigen::VectorXd::Zero(dofs.num_dofs());
      faces.evaluate(u, f);
      Eigen::Vector2d on_cell1 = Eigen::Vector2d::Zero();
      for (int j = 0; j < p.model.mesh.cell_size(cell1); ++j)
        on_cell1 += f.segment<2>(2 * dofs.node(cell1, j));
      const Eigen::Vector2d expected = k * delta * p.length * (R * p.n);
      if (turning)
        EXPECT_LT((on_cell1 - expected).norm(), 1e-9 * expected.norm()) << "theta " << theta;
      else
        EXPECT_GT((on_cell1 - expected).norm(), 0.1 * expected.norm()) << "theta " << theta;
    }
  }
}

TEST(CohesiveFriction, ATurningFramesForceIsItsEnergysGradient) {
  // A broken face (the law carries nothing), its two cells turned, pressed together and
  // sheared by an arbitrary field: the force is minus the gradient of the closure's energy
  // k <g_n>^2 / 2 read in the turning frame, frame's own dependence on u included (central
  // differences, to 1e-6).
  Pair p;
  const SplitDofMap dofs(p.model.mesh, split_at(p));
  CohesiveForces faces(p.model.mesh, p.law);
  faces.set_turning_frames(true);
  faces.add_edge(p.edge);
  faces.bind(dofs);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(dofs.num_dofs());
  faces.evaluate(p.displacement(dofs, 3.0 * p.law.critical_opening(), 0.0), f);
  ASSERT_TRUE(faces.broken(p.edge));
  const int cell1 = p.model.mesh.edge(p.edge).cell1;
  const Eigen::Matrix2d R = Eigen::Rotation2Dd(0.7).toRotationMatrix();
  Eigen::VectorXd u(dofs.num_dofs());
  for (int c = 0; c < p.model.mesh.num_cells(); ++c)
    for (int j = 0; j < p.model.mesh.cell_size(c); ++j) {
      const Point X = p.model.mesh.vertex(p.model.mesh.cell_vertices(c)[j]);
      const Point x = R * (c == cell1 ? Point(X - 2e-7 * p.n + 1e-4 * p.t) : X);
      u.segment<2>(2 * dofs.node(c, j)) = x - X;
    }
  u += testing::random_vector(dofs.num_dofs(), 3e-8, 5);
  auto energy = [&](const Eigen::VectorXd& at) {
    Eigen::VectorXd g = Eigen::VectorXd::Zero(dofs.num_dofs());
    faces.evaluate(at, g);
    return faces.stored_energy();
  };
  f.setZero();
  faces.evaluate(u, f);
  const double h = 1e-11;
  double worst = 0.0;
  for (int i = 0; i < dofs.num_dofs(); ++i) {
    Eigen::VectorXd up = u, down = u;
    up[i] += h, down[i] -= h;
    const double numeric = -(energy(up) - energy(down)) / (2 * h);
    worst = std::max(worst, std::abs(numeric - f[i]));
  }
  EXPECT_LT(worst, 1e-6 * f.norm()) << "force scale " << f.norm();
}

TEST(CohesiveFriction, RefusesABadCoefficient) {
  Pair p;
  CohesiveForces faces(p.model.mesh, p.law);
  EXPECT_THROW(faces.set_friction(-0.1), InputError);
  EXPECT_THROW(faces.set_friction(std::nan("")), InputError);
}

}  // namespace
}  // namespace vorodg
