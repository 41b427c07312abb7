// Activation of coupled interfaces by the criterion (dynamics/InterfaceActivation), the report's
// second crack approach in explicit dynamics, on a ceramic strip of rcp cells (2 x 0.4 mm,
// h = 0.1 mm, E = 275 GPa, nu = 0.2, rho = 2750 kg/m^3; linear softening sigma_c = 300 MPa,
// G = 100 J/m^2, K0 = E / h; Mohr-Coulomb cutoff 300 MPa, cohesion 600 MPa) with every interior
// edge split and coupled from t = 0:
//   - continuity: an interface activated under a stress within the law's strength continues
//     with the traction it carried. The cohesive face's own evaluation (its jump from the bound
//     nodes, its frame) at the same displacements gives, at each Gauss point, the traction the
//     coupling's flux gave to 1e-9 of the stress, and the activation creates no energy beyond
//     the difference of two quadratic forms (reported);
//   - stretched by v = rate (x - x_mid) at rate 1e5 /s: cracks form, the integrator's discrete
//     balance (with the activation energy) closes to 1e-10 of the initial kinetic energy, and
//     the law's balance (kinetic + elastic + dissipated + stored = initial + activation work)
//     within 2e-2 (the trapezoid against the closed forms, as with insertion);
//   - 1 and 2 threads give the same activations and the same displacements, bit for bit;
//   - with a criterion no traction reaches, 1e4 steps are bit for bit the coupled run without
//     activation (same DOFs, same forces): the check changes nothing.
#include "dynamics/InterfaceActivation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/util/Errors.hpp"
#include "dynamics/DynamicFracture.hpp"
#include "support/DynamicsModel.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;

constexpr double kE = 275e9, kDensity = 2750.0, kStrength = 300e6, kH = 1e-4;
constexpr double kLength = 2e-3, kHeight = 4e-4;

struct Strip {
  DynamicsModel model{mesh_spec(MeshFamily::rcp, Rectangle(0, 0, kLength, kHeight), kH, 11),
                      IsotropicElasticity(kE, 0.2, PlaneModel::stress), kDensity};
  SplitDofMap dofs = SplitDofMap::discontinuous(model.mesh);
  InterfaceCoupling coupling{model.table, model.integrator, model.matrices, dofs};
  CohesiveLaw law{CohesiveParameters{kStrength, 100.0, 1.0, "linear", kE / kH}};
  std::vector<char> every_edge = std::vector<char>(model.mesh.num_edges(), 1);

  double stable_step(double safety) const {
    return safety * 2.0 /
           std::sqrt(model.limit.max_eigenvalue() +
                     coupling.eigenvalue_bound(model.mass.node_masses(dofs)) +
                     CohesiveForces::eigenvalue_bound(model.mesh, model.mass, law, every_edge));
  }
};

MohrCoulomb criterion(double cutoff) {
  return MohrCoulomb(MohrCoulombParameters{2.0 * cutoff, 0.0, cutoff});
}

TEST(InterfaceActivation, AnActivatedFaceContinuesWithTheTractionItCarried) {
  Strip s;
  // A uniform tension of 100 MPa along x with a small shear, plus small random jumps.
  Eigen::Matrix2d G;
  G << 100e6 / kE, 20e6 / kE, 0.0, -0.2 * 100e6 / kE;
  Eigen::VectorXd u(s.dofs.num_dofs());
  for (int c = 0; c < s.model.mesh.num_cells(); ++c)
    for (int k = 0; k < s.model.mesh.cell_size(c); ++k)
      u.segment<2>(2 * s.dofs.node(c, k)) =
          G * s.model.mesh.vertex(s.model.mesh.cell_vertices(c)[k]);
  u += random_vector(u.size(), 1e-3 * 100e6 / kE * kH, 3);
  // Everything fails a 1 Pa cutoff; the law (300 MPa) carries all of it on its elastic branch.
  InterfaceActivation activation(s.model.mesh, s.coupling, criterion(1.0), s.every_edge);
  const auto failing = activation.failing(u, 1);
  ASSERT_EQ(static_cast<int>(failing.size()), s.coupling.num_interfaces());
  std::vector<std::array<Eigen::Vector2d, 2>> carried;
  for (const auto& f : failing) carried.push_back(activation.face_tractions(f.interface, u));
  CohesiveForces cohesive(s.model.mesh, s.law);
  activation.activate(failing, u, cohesive);
  cohesive.bind(s.dofs);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(u.size());
  cohesive.evaluate(u, f);
  double worst = 0.0;
  for (std::size_t k = 0; k < failing.size(); ++k)
    for (int q = 0; q < 2; ++q)
      worst = std::max(worst, (cohesive.point_traction(failing[k].edge, q) - carried[k][q]).norm());
  std::printf(
      "largest traction jump at activation %.2e Pa (stress 1e8 Pa); activation work "
      "%.3e J/m against the law's starting energy %.3e J/m\n",
      worst, activation.activation_work(), cohesive.continuation_energy());
  EXPECT_LT(worst, 1e-9 * 100e6);
  for (int i = 0; i < s.coupling.num_interfaces(); ++i) EXPECT_FALSE(s.coupling.active(i));
}

struct Stretched {
  std::vector<CrackEvent> events;
  Eigen::VectorXd u;
  double balance = 0.0, law_balance = 0.0, activation_work = 0.0;
  int activated = 0;
};

/// Stretches the strip for `end` seconds (or `steps`, if > 0); activation on unless `activate`
/// is false.
Stretched stretch(double cutoff, int threads, double end, bool activate = true, long steps = 0) {
  Strip s;
  DynamicsOptions options;
  options.threads = threads;
  CentralDifference run(s.model.mesh, s.model.mass, InternalForce(s.model.mesh, s.model.matrices),
                        s.dofs, s.stable_step(0.9), options);
  run.set_interface_coupling(s.coupling);
  CohesiveForces cohesive(s.model.mesh, s.law);
  const MohrCoulomb mc = criterion(cutoff);
  CrackInsertion insertion(s.model.mesh, s.model.integrator, mc, s.every_edge, threads);
  DynamicFracture fracture(s.model.mesh, run, cohesive, insertion);
  InterfaceActivation activation(s.model.mesh, s.coupling, mc, s.every_edge);
  fracture.set_activation(activation);
  Eigen::VectorXd v0(run.dofs().num_dofs());
  for (int i = 0; i < run.dofs().num_nodes(); ++i)
    v0.segment<2>(2 * i) = Eigen::Vector2d(1e5 * (run.node_position(i).x() - 0.5 * kLength), 0);
  run.initialize(Eigen::VectorXd::Zero(v0.size()), v0);
  const double k0 = run.record().kinetic, b0 = run.record().balance();
  Stretched out;
  while (steps > 0 ? run.step_count() < steps : run.time() < end) {
    if (activate)
      fracture.step(threads);
    else
      run.step();
    const StepRecord& r = run.record();
    out.balance = std::max(out.balance, std::abs(r.balance() - b0) / k0);
    const double law = cohesive.dissipated_energy() + cohesive.stored_energy();
    out.law_balance =
        std::max(out.law_balance,
                 std::abs(r.kinetic + r.elastic + law - k0 - activation.activation_work()) / k0);
  }
  out.events = fracture.events();
  out.u = run.displacement();
  out.activation_work = activation.activation_work() / k0;
  out.activated = activation.activated();
  return out;
}

TEST(InterfaceActivation, AStretchedStripCracksWithItsBalanceClosed) {
  const double end = 20.0 * kStrength / (kE * 1e5);
  const Stretched one = stretch(kStrength, 1, end), two = stretch(kStrength, 2, end);
  std::printf(
      "activated %d interfaces; discrete balance %.2e, law balance %.2e, activation "
      "work %.2e of the initial kinetic energy\n",
      one.activated, one.balance, one.law_balance, one.activation_work);
  EXPECT_GT(one.activated, 5);
  EXPECT_LT(one.balance, 1e-10);
  EXPECT_LT(one.law_balance, 2e-2);
  ASSERT_EQ(one.events.size(), two.events.size());
  for (std::size_t k = 0; k < one.events.size(); ++k) {
    EXPECT_EQ(one.events[k].step, two.events[k].step);
    EXPECT_EQ(one.events[k].edge, two.events[k].edge);
  }
  EXPECT_EQ(one.u, two.u);
}

TEST(InterfaceActivation, BelowTheStrengthTheCheckChangesNothing) {
  // 1e4 steps: the strip rings (its ends are free), and the coupled run, with the check or
  // without it, is the same to the bit.
  const Stretched checked = stretch(1e6 * kStrength, 1, 0.0, true, 10000),
                  plain = stretch(1e6 * kStrength, 1, 0.0, false, 10000);
  EXPECT_EQ(checked.activated, 0);
  EXPECT_EQ(checked.u, plain.u);
}

TEST(InterfaceActivation, RefusesAnEdgeThatIsNotCoupled) {
  Strip s;
  // A continuous map couples nothing: an eligible interior edge is refused by number.
  const SplitDofMap continuous = SplitDofMap::continuous(s.model.mesh);
  InterfaceCoupling none(s.model.table, s.model.integrator, s.model.matrices, continuous);
  EXPECT_THROW(InterfaceActivation(s.model.mesh, none, criterion(kStrength), s.every_edge),
               InputError);
  EXPECT_THROW(InterfaceActivation(s.model.mesh, s.coupling, criterion(kStrength), {1, 0}),
               InputError);
}

}  // namespace
}  // namespace vorodg
