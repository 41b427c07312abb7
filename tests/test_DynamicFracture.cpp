// Extrinsic dynamic fracture (dynamics/DynamicFracture, CohesiveForces, CrackInsertion) on the
// one-dimensional fragmentation benchmark: a strip one quad cell high (h = 10 um, 2 mm long),
// stretched by the initial velocity v = rate (x - x_mid), free ends, nu = 0, so that every
// interior edge is a whole cross section and the stress is uniaxial. Alumina-like ceramic
// (E = 275 GPa, rho = 2750 kg/m^3, sigma_c = 300 MPa); linear softening. The step is
// 0.9 x 2 / sqrt(cells' bound + springs' bound). Two settings:
//   - "brittle" (G = 0.01 J/m^2, K0 = 1e3 E / h, rate 1e7 /s, as in Akantu's extrinsic
//     fragmentation test, where every section breaks at once): neighbours separate at
//     rate h = 100 m/s, far above the speed sigma_c / (rho c) = 11 m/s at which a released cell
//     vibrates, so fragments do not touch again (at 1e5 /s they rattle against each other
//     through the overclosure penalty and trade momentum: 12 % of rate L / 2, measured).
//     Checked: fragments number one more than the broken cross sections; their masses sum to
//     the total to round-off; node masses after every split sum to the lumped total to 1e-14;
//     the momentum (zero at the start) stays within 1e-10 of sum m |v| through every split;
//     late fragment velocities equal rate x (centre - x_mid) within 1 % of rate x L / 2
//     (measured 1e-4) for fragments farther than the release length from an end (below); the
//     discrete energy balance closes to 1e-10;
//   - "alumina" (G = 100 J/m^2, K0 = E / h, rate 1e5 /s, fragments of several cells): the
//     dissipation of every fully broken edge is G x its length to 1e-12; the cohesive work the
//     integrator books (the trapezoid) against the law's closed form (dissipated + stored):
//     their difference is the step's error at the law's kinks and shrinks as dt^2 (at least
//     50-fold for a 10-fold smaller step; measured 120-fold), and at the default step the
//     physical balance (kinetic + elastic + dissipated + stored = initial kinetic) closes to 2 %
//     (measured 1.3 %);
//   - 1 and 2 threads give the same crack events and the same displacements, bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/util/Errors.hpp"
#include "dynamics/DynamicFracture.hpp"
#include "fracture/Fragments.hpp"
#include "support/DynamicsModel.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;

constexpr double kE = 275e9, kDensity = 2750.0, kStrength = 300e6;
constexpr double kLength = 0.002, kHeight = 1e-5;

struct Strip {
  Strip(double toughness, double stiffness, double strain_rate)
      : law(CohesiveParameters{kStrength, toughness, 1.0, "linear", stiffness * kE / kHeight}),
        rate(strain_rate) {}
  DynamicsModel model{mesh_spec(MeshFamily::quad, Rectangle(0, 0, kLength, kHeight), kHeight),
                      IsotropicElasticity(kE, 0.0, PlaneModel::stress), kDensity};
  CohesiveLaw law;
  MohrCoulomb criterion{MohrCoulombParameters{10 * kStrength, 0.0, kStrength}};
  double rate;  // 1/s
};

/// What a run leaves: its end state (the map and crack state live on, so they are built at the
/// end), and the worst values met on the way.
struct Outcome {
  Outcome(SplitDofMap map, CrackState broken_edges)
      : dofs(std::move(map)), broken_state(std::move(broken_edges)) {}
  SplitDofMap dofs;
  CrackState broken_state;
  std::vector<CrackEvent> events;
  Eigen::VectorXd u, v;
  StepRecord record;
  double dissipated = 0.0, stored = 0.0, broken_error = 0.0;
  int broken = 0;
  int cracked_in_state = 0;       // CrackState::num_cracked of the crack state with openings
  double smallest_opening = 0.0;  // over its cracked edges
  double momentum = 0.0, mass = 0.0, balance = 0.0, physical = 0.0;
};

/// Stretches the strip for 20 x the time the stress needs to reach the strength.
Outcome stretch(const Strip& strip, double safety, int threads) {
  const DynamicsModel& m = strip.model;
  DynamicsOptions options;
  options.threads = threads;
  const std::vector<char> every_edge(m.mesh.num_edges(), 1);
  // The cells' bound holds for every split of the map; the faces' springs add theirs.
  auto run = m.integrator_with(
      CohesiveForces::stable_step(m.limit, m.mesh, m.mass, strip.law, every_edge, safety), options);
  CohesiveForces cohesive(m.mesh, strip.law);
  CrackInsertion insertion(m.mesh, m.integrator, strip.criterion, every_edge, threads);
  DynamicFracture fracture(m.mesh, *run, cohesive, insertion);
  Eigen::VectorXd v0(run->dofs().num_dofs());
  for (int i = 0; i < run->dofs().num_nodes(); ++i)
    v0.segment<2>(2 * i) =
        Eigen::Vector2d(strip.rate * (run->node_position(i).x() - 0.5 * kLength), 0);
  run->initialize(Eigen::VectorXd::Zero(v0.size()), v0);
  const double k0 = run->record().kinetic, b0 = run->record().balance();
  Outcome out(run->dofs(), fracture.broken_state());
  const double end = 20.0 * kStrength / (kE * strip.rate);
  while (run->time() < end) {
    const int cracked = fracture.step(threads);
    const StepRecord& r = run->record();
    out.balance = std::max(out.balance, std::abs(r.balance() - b0) / k0);
    const double law = cohesive.dissipated_energy() + cohesive.stored_energy();
    out.physical = std::max(out.physical, std::abs(r.kinetic + r.elastic + law - k0) / k0);
    if (cracked == 0) continue;
    double mv = 0.0;
    for (int i = 0; i < run->dofs().num_nodes(); ++i)
      mv += run->node_masses()[i] * run->velocity().segment<2>(2 * i).norm();
    out.momentum = std::max(out.momentum, r.momentum.norm() / mv);
    out.mass =
        std::max(out.mass, std::abs(run->node_masses().sum() - m.mass.total()) / m.mass.total());
  }
  out.events = fracture.events();
  out.u = run->displacement();
  out.v = run->velocity();
  out.dofs = run->dofs();
  out.record = run->record();
  out.dissipated = cohesive.dissipated_energy();
  out.stored = cohesive.stored_energy();
  out.broken = cohesive.num_broken();
  out.broken_state = fracture.broken_state();
  const CrackState cracks = fracture.crack_state();
  out.cracked_in_state = cracks.num_cracked();
  out.smallest_opening = INFINITY;
  for (int e : cohesive.edges())
    out.smallest_opening = std::min(out.smallest_opening, cracks.openings()[e]);
  for (int e : cohesive.edges())
    if (cohesive.broken(e))
      out.broken_error =
          std::max(out.broken_error,
                   std::abs(cohesive.dissipated_energy(e) -
                            strip.law.parameters().fracture_energy * m.mesh.edge_length(e)) /
                       (strip.law.parameters().fracture_energy * kHeight));
  return out;
}

TEST(DynamicFracture, BrittleStripFragmentsKeepTheirVelocity) {
  const Strip strip(0.01, 1e3, 1e7);
  const Outcome out = stretch(strip, 0.9, 1);
  const Fragments fragments(out.broken_state, strip.model.mass.pair_masses());
  const Eigen::Matrix2Xd velocity = fragments.velocities(out.dofs, out.v);
  // Fragments within the release length l = c t_c of an end (c = sqrt(E / rho), t_c the time
  // the stress takes to reach the strength) are left out: before anything broke, the unloading
  // wave from the free end made the tension there grow towards the inside, so it pulled them
  // inwards (about sigma_c t_c / (2 rho l_end) = 6 m/s for the end fragments, measured 7.7).
  // Beyond l the tension was uniform and pulled each fragment from both sides alike.
  const double release = std::sqrt(kE / kDensity) * kStrength / (kE * strip.rate);
  double error = 0.0, end_error = 0.0;
  for (int f = 0; f < fragments.num_fragments(); ++f) {
    const double x = fragments.centres()(0, f);
    const double e = std::abs(velocity(0, f) - strip.rate * (x - 0.5 * kLength));
    const bool near_end = std::min(x, kLength - x) < release;
    (near_end ? end_error : error) = std::max(near_end ? end_error : error, e);
  }
  std::printf(
      "strip, brittle: %d cells, %zu cracked, %d broken, %d fragments; velocity error of the "
      "fragments beyond the release length %.2e of rate L/2 (within it %.2e); momentum %.2e, mass "
      "%.2e, balance "
      "%.2e\n",
      strip.model.mesh.num_cells(), out.events.size(), out.broken, fragments.num_fragments(),
      error / (0.5 * strip.rate * kLength), end_error / (0.5 * strip.rate * kLength), out.momentum,
      out.mass, out.balance);
  EXPECT_GT(out.broken, strip.model.mesh.num_cells() / 2);
  // The crack state with openings: every cracked edge, each opened (a broken one past delta_c).
  EXPECT_EQ(out.cracked_in_state, static_cast<int>(out.events.size()));
  EXPECT_GT(out.smallest_opening, 0.0);
  EXPECT_EQ(fragments.num_fragments(), out.broken + 1);
  EXPECT_NEAR(fragments.masses().sum(), fragments.total_mass(), 1e-14 * fragments.total_mass());
  EXPECT_LT(out.mass, 1e-14);
  EXPECT_LT(out.momentum, 1e-10);
  EXPECT_LT(out.balance, 1e-10);
  EXPECT_LT(error, 0.01 * 0.5 * strip.rate * kLength);
}

TEST(DynamicFracture, CohesiveWorkConvergesToTheLawsEnergy) {
  const Strip strip(100.0, 1.0, 1e5);
  double mismatch[2];
  for (int k = 0; k < 2; ++k) {
    const double safety = k == 0 ? 0.9 : 0.09;
    const Outcome out = stretch(strip, safety, 1);
    const double law = out.dissipated + out.stored;
    mismatch[k] = std::abs(-out.record.cohesive_work - law) / out.dissipated;
    std::printf(
        "strip, alumina, safety %.2f: %ld steps, %zu cracked, %d broken; -cohesive work %.6e "
        "J/m, law %.6e (rel %.2e); broken edges' dissipation vs G L %.1e; physical balance "
        "%.2e, discrete %.2e\n",
        safety, out.record.step, out.events.size(), out.broken, -out.record.cohesive_work, law,
        mismatch[k], out.broken_error, out.physical, out.balance);
    EXPECT_GT(out.broken, 1);
    EXPECT_LT(out.broken_error, 1e-12);
    EXPECT_LT(out.balance, 1e-10);
    if (k == 0) {
      EXPECT_LT(out.physical, 0.02);
    }
  }
  EXPECT_GT(mismatch[0] / mismatch[1], 50.0);
}

TEST(DynamicFracture, ThreadCountDoesNotChangeTheCracks) {
  const Strip strip(100.0, 1.0, 1e5);
  const Outcome one = stretch(strip, 0.9, 1), two = stretch(strip, 0.9, 2);
  ASSERT_EQ(one.events.size(), two.events.size());
  for (std::size_t i = 0; i < one.events.size(); ++i) {
    EXPECT_EQ(one.events[i].step, two.events[i].step);
    EXPECT_EQ(one.events[i].edge, two.events[i].edge);
  }
  EXPECT_TRUE(one.u == two.u);
}

TEST(DynamicFracture, DynamicsRefusesAPurelyExtrinsicLaw) {
  const Strip strip(100.0, 1.0, 1e5);
  const CohesiveLaw extrinsic(CohesiveParameters{kStrength, 100.0, 1.0});
  EXPECT_THROW(CohesiveForces(strip.model.mesh, extrinsic), InputError);
}

}  // namespace
}  // namespace vorodg
