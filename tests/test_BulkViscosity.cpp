// Bulk viscosity on the cells (dynamics/BulkViscosity) in the explicit integrator:
//   - a cell in a uniform dilation rate gets q from the closed form (linear, and quadratic only
//     in compression), to 1e-12; a pure shear rate and a rigid rotation rate give q = 0;
//   - the nodal force is the exact virtual work of q I: v.f = -sum_c q_c A_c eps_c, to 1e-12;
//   - the step factor sqrt(1 + xi^2) - xi and its inverse; a compression too fast for the
//     chosen step is refused with a NumericalError;
//   - a free body started in a dilation: the energy balance with bulk_viscosity_dissipation
//     closes to round-off, the dissipation grows, momentum stays, one and two threads agree
//     bit for bit;
//   - the wave bar (problem wave-bar, rollers): b1 = 0.06, b2 = 1.2 lower the overshoot behind a
//     steep front against no bulk viscosity, and the wave speed stays within 0.5 % of the run
//     without it.
#include <gtest/gtest.h>
#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/util/Errors.hpp"
#include "dynamics/BulkViscosity.hpp"
#include "dynamics/GlobalTimeStep.hpp"
#include "dynamics/problems/DynamicsProbe.hpp"
#include "support/DynamicsModel.hpp"
#include "verification/kinds/dynamics/DynamicsRun.hpp"

namespace vorodg {
namespace {

using TestModel = testing::DynamicsModel;

constexpr double kRho = 2.0, kB1 = 0.06, kB2 = 1.2;
const IsotropicElasticity kMaterial(1.0, 0.3, PlaneModel::strain);

/// The dilatational speed sqrt((lambda + 2 mu) / rho) of the material in plane strain.
double dilatational_speed() {
  return std::sqrt((kMaterial.lambda() + 2.0 * kMaterial.mu()) / kRho);
}

/// An rcp body [0, 1] x [0, 0.5] and its bulk viscosity.
struct Body {
  explicit Body(double size = 0.1)
      : model(testing::mesh_spec(MeshFamily::rcp, Rectangle(0, 0, 1, 0.5), size), kMaterial, kRho) {
  }
  TestModel model;
  SplitDofMap dofs = SplitDofMap::continuous(model.mesh);

  BulkViscosity bulk(double b1 = kB1, double b2 = kB2) const {
    return BulkViscosity(model.mesh, {b1, b2}, kRho,
                         std::vector<double>(model.mesh.num_cells(), dilatational_speed()));
  }
  /// Node velocities v = G (X - X0).
  Eigen::VectorXd linear_field(const Eigen::Matrix2d& g) const {
    Eigen::VectorXd v(dofs.num_dofs());
    for (int c = 0; c < model.mesh.num_cells(); ++c)
      for (int k = 0; k < model.mesh.cell_size(c); ++k)
        v.segment<2>(2 * dofs.node(c, k)) =
            g * (model.mesh.vertex(model.mesh.cell_vertices(c)[k]) - Point(0.4, 0.3));
    return v;
  }
  /// Cell c's area by the shoelace formula, apart from MeanGradient's.
  double area(int c) const {
    const auto loop = model.mesh.cell_vertices(c);
    double twice = 0.0;
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Point a = model.mesh.vertex(loop[k]),
                  b = model.mesh.vertex(loop[(k + 1) % loop.size()]);
      twice += a.x() * b.y() - b.x() * a.y();
    }
    return 0.5 * std::abs(twice);
  }
};

/// The closed form: q = b1 rho c L eps - rho (b2 L)^2 eps min(0, eps), L = sqrt(A).
double closed_form(double area, double eps) {
  const double L = std::sqrt(area), c = dilatational_speed();
  return kB1 * kRho * c * L * eps - kRho * kB2 * kB2 * L * L * eps * std::min(0.0, eps);
}

TEST(BulkViscosity, UniformDilationRateGivesTheClosedForm) {
  const Body body;
  BulkViscosity bulk = body.bulk();
  Eigen::VectorXd f;
  for (double r : {0.3, -0.3}) {  // expansion (linear term only), compression (both)
    bulk.compute(body.dofs, body.linear_field(r * Eigen::Matrix2d::Identity()), f, 1);
    double worst_rate = 0.0, worst_q = 0.0;
    for (int c = 0; c < body.model.mesh.num_cells(); ++c) {
      const double eps = bulk.cell_rate(c), expected = closed_form(body.area(c), 2.0 * r);
      worst_rate = std::max(worst_rate, std::abs(eps / (2.0 * r) - 1.0));
      worst_q = std::max(worst_q, std::abs(bulk.pressure(c, eps) / expected - 1.0));
    }
    std::printf("dilation rate %+.1f: rate error %.1e, q error %.1e (relative)\n", 2 * r,
                worst_rate, worst_q);
    EXPECT_LT(worst_rate, 1e-12);
    EXPECT_LT(worst_q, 1e-12);
  }
  // The quadratic term acts in compression only, and always against the rate.
  EXPECT_EQ(bulk.pressure(0, 0.6), BulkViscosity(body.bulk(kB1, 0.0)).pressure(0, 0.6));
  EXPECT_LT(bulk.pressure(0, -0.6), BulkViscosity(body.bulk(kB1, 0.0)).pressure(0, -0.6));
  EXPECT_GT(bulk.pressure(0, 0.6), 0.0);
}

TEST(BulkViscosity, ShearAndRotationRatesGiveNone) {
  const Body body;
  BulkViscosity bulk = body.bulk();
  Eigen::VectorXd f;
  Eigen::Matrix2d shear, spin;
  shear << 0.0, 0.3, 0.3, 0.0;
  spin << 0.0, -0.3, 0.3, 0.0;
  bulk.compute(body.dofs, body.linear_field(0.3 * Eigen::Matrix2d::Identity()), f, 1);
  const double scale = f.norm();
  for (const Eigen::Matrix2d& g : {shear, spin}) {
    bulk.compute(body.dofs, body.linear_field(g), f, 1);
    double largest = 0.0;
    for (int c = 0; c < body.model.mesh.num_cells(); ++c)
      largest = std::max(largest, std::abs(bulk.cell_rate(c)));
    EXPECT_LT(largest, 1e-14);
    EXPECT_LT(f.norm(), 1e-13 * scale);
  }
}

TEST(BulkViscosity, ForceIsTheExactVirtualWork) {
  const Body body;
  BulkViscosity bulk = body.bulk();
  const Eigen::VectorXd v = testing::random_vector(body.dofs.num_dofs(), 0.5, 11);
  Eigen::VectorXd f;
  bulk.compute(body.dofs, v, f, 1);
  double expected = 0.0, scale = 0.0;
  for (int c = 0; c < body.model.mesh.num_cells(); ++c) {
    const double eps = bulk.cell_rate(c), work = bulk.pressure(c, eps) * body.area(c) * eps;
    expected -= work;
    scale += std::abs(work);
  }
  std::printf("virtual work: v.f = %.6e, -sum q A eps = %.6e\n", v.dot(f), expected);
  EXPECT_LT(expected, 0.0);  // it only takes energy out
  EXPECT_NEAR(v.dot(f), expected, 1e-12 * scale);
  // Each cell's force is self-equilibrated: it moves no momentum.
  Eigen::Vector2d total = Eigen::Vector2d::Zero();
  for (int i = 0; i < body.dofs.num_nodes(); ++i) total += f.segment<2>(2 * i);
  EXPECT_LT(total.norm(), 1e-14 * f.norm());
}

TEST(BulkViscosity, TurnedCellsReadTheRateOfTheirCurrentVolume) {
  // The body turned rigidly by theta (up to 10 rad) and scaled by s: x = s R X. Spinning at
  // omega it keeps its volume: no rate, no force, where the reference cell would read
  // -2 omega sin theta. Growing at ds/dt: dJ/dt / J = 2 (ds/dt) / s. And the force is the
  // virtual work of q on the current area: v.f = -sum q A dJ/dt.
  const Body body;
  BulkViscosity bulk = body.bulk();
  bulk.set_current_configuration(true);
  Eigen::Matrix2d J;
  J << 0.0, -1.0, 1.0, 0.0;
  for (const double theta : {0.5, 3.0, 10.0}) {
    const double s = 1.01;
    const Eigen::Matrix2d R = Eigen::Rotation2Dd(theta).toRotationMatrix();
    const Eigen::VectorXd u = body.linear_field(s * R - Eigen::Matrix2d::Identity());
    Eigen::VectorXd f;
    bulk.compute(body.dofs, body.linear_field(0.3 * J * R), f, 1, &u);
    double largest = 0.0;
    for (int c = 0; c < body.model.mesh.num_cells(); ++c)
      largest = std::max(largest, std::abs(bulk.cell_rate(c)));
    EXPECT_LT(largest, 1e-13) << "theta " << theta;
    const double growth = 0.2;  // ds/dt
    const Eigen::VectorXd v = body.linear_field(growth * R);
    bulk.compute(body.dofs, v, f, 1, &u);
    double worst = 0.0, expected = 0.0, scale = 0.0;
    for (int c = 0; c < body.model.mesh.num_cells(); ++c) {
      const double eps = bulk.cell_rate(c);
      worst = std::max(worst, std::abs(eps / (2.0 * growth / s) - 1.0));
      const double work = bulk.pressure(c, eps) * body.area(c) * s * s * eps;  // q A J eps
      expected -= work;
      scale += std::abs(work);
    }
    EXPECT_LT(worst, 1e-12) << "theta " << theta;
    EXPECT_NEAR(v.dot(f), expected, 1e-12 * scale) << "theta " << theta;
  }
}

TEST(BulkViscosity, StepFactorAndTheQuadraticTermsCheck) {
  for (double r : {0.3, 0.8, 0.9 * BulkViscosity::step_factor(kB1)})
    EXPECT_NEAR(BulkViscosity::step_factor(BulkViscosity::allowed_damping_ratio(r)), r, 1e-14);
  EXPECT_NEAR(BulkViscosity::step_factor(0.06), 0.941798, 1e-6);
  EXPECT_TRUE(std::isinf(BulkViscosity::allowed_damping_ratio(1.0)));
  const Body body;
  BulkViscosity bulk = body.bulk(kB1, 10.0);
  bulk.set_step_ratio(0.9 * BulkViscosity::step_factor(kB1));
  Eigen::VectorXd f;
  // xi = b1 + b2^2 L |eps| / c_d: 0.06 + 100 x 0.1 x 1e-3 / 0.93 = 0.071, allowed 0.17.
  EXPECT_NO_THROW(
      bulk.compute(body.dofs, body.linear_field(-5e-4 * Eigen::Matrix2d::Identity()), f, 1));
  // At a rate 100 times faster xi passes 1: refused, naming the cell.
  try {
    bulk.compute(body.dofs, body.linear_field(-5e-2 * Eigen::Matrix2d::Identity()), f, 1);
    ADD_FAILURE() << "no NumericalError";
  } catch (const NumericalError& e) {
    std::printf("%s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("bulk viscosity: cell"), std::string::npos);
  }
  EXPECT_THROW(BulkViscosity(body.model.mesh, {-0.1, 0.0}, kRho,
                             std::vector<double>(body.model.mesh.num_cells(), 1.0)),
               InputError);
}

/// A free body started in a uniform dilation plus some of every frequency, with bulk
/// viscosity, at 0.9 x the Lanczos step cut by the linear term's factor; initialized.
std::unique_ptr<CentralDifference> dilating_body(const Body& body, BulkViscosity& bulk,
                                                 int threads = 1) {
  const double ratio = 0.9 * BulkViscosity::step_factor(kB1);
  InternalForce force(body.model.mesh, body.model.matrices);
  const double critical =
      GlobalTimeStep(force, body.dofs, body.model.mass.node_masses(body.dofs), body.model.limit)
          .critical();
  bulk.set_step_ratio(ratio);
  auto run = std::make_unique<CentralDifference>(body.model.mesh, body.model.mass, std::move(force),
                                                 body.dofs, ratio * critical,
                                                 DynamicsOptions{0.0, threads});
  run->set_bulk_viscosity(bulk);
  Eigen::VectorXd v = body.linear_field(1e-2 * Eigen::Matrix2d::Identity());
  v += testing::random_vector(v.size(), 1e-3, 5);
  run->initialize(Eigen::VectorXd::Zero(v.size()), v);
  return run;
}

TEST(BulkViscosity, EnergyBalanceClosesOnADilatingFreeBody) {
  const Body body;
  BulkViscosity bulk = body.bulk();
  const auto run = dilating_body(body, bulk);
  const StepRecord start = run->record();
  double scale = 0.0;  // sum m |v|
  for (int i = 0; i < body.dofs.num_nodes(); ++i)
    scale += run->node_masses()[i] * run->velocity().segment<2>(2 * i).norm();
  double drift = 0.0, momentum = 0.0, max_xi = 0.0;
  for (int s = 0; s < 4000; ++s) {
    const StepRecord& r = run->step();
    drift = std::max(drift, std::abs(r.balance() - r.initial_balance) / r.input_energy());
    momentum = std::max(momentum, (r.momentum - start.momentum).norm() / scale);
    max_xi = std::max(max_xi, bulk.max_damping_ratio());
  }
  const StepRecord& r = run->record();
  std::printf(
      "dilating free body, %d cells, 4000 steps: balance drift %.2e of the input, bulk viscosity "
      "took %.3f of it (kinetic + elastic left %.3f), momentum drift %.1e, largest xi %.4f\n",
      body.model.mesh.num_cells(), drift, r.bulk_viscosity_dissipation / r.input_energy(),
      (r.kinetic_leapfrog + r.elastic) / r.input_energy(), momentum, max_xi);
  EXPECT_LT(drift, 1e-12);
  EXPECT_GT(r.bulk_viscosity_dissipation, 0.1 * r.input_energy());
  EXPECT_LT(momentum, 1e-13);
  EXPECT_GT(max_xi, kB1);  // the quadratic term acted
}

TEST(BulkViscosity, OneAndTwoThreadsAgreeBitForBit) {
  const Body body(0.015);  // several chunks of cells and nodes
  ASSERT_GT(body.model.mesh.num_cells(), 1024);
  BulkViscosity one = body.bulk(), two = body.bulk();
  const auto a = dilating_body(body, one, 1), b = dilating_body(body, two, 2);
  for (int s = 0; s < 50; ++s) a->step(), b->step();
  EXPECT_EQ(a->velocity(), b->velocity());
  EXPECT_EQ(a->displacement(), b->displacement());
  EXPECT_EQ(a->record().bulk_viscosity_dissipation, b->record().bulk_viscosity_dissipation);
  EXPECT_EQ(a->record().balance(), b->record().balance());
}

/// The wave bar of problem wave-bar (steel, 1 x 0.05 m, rollers: uniaxial strain, hex h =
/// 0.0125) with the pulse `duration` (in L / c) and bulk viscosity `bulk` ("" for none).
std::string wave_bar(double duration, const std::string& bulk) {
  const double c = std::sqrt(2e11 * 0.7 / (7800 * 1.3 * 0.4));
  return R"({"study": "dynamics", "problem": "wave-bar", "sides": "rollers",
    "material": {"E": 2e11, "nu": 0.3, "density": 7800, "plane": "strain"},
    "pulse": {"duration": )" +
         std::to_string(duration / c) + R"(}, "outputs": {"vtu": false},
    "meshes": [{"family": "hex", "sizes": [0.0125]}])" +
         (bulk.empty() ? "" : ", " + bulk) + "}";
}

struct BarMeasures {
  double peak = 0.0;         // the largest velocity at x = L / 2 over the amplitude
  double speed_error = NAN;  // the problem's own: arrival at the far end against L / c
  double dissipated = 0.0;   // bulk_viscosity_dissipation over the input, at the end
  double balance = 0.0;      // the largest balance drift over the input
  double max_xi = 0.0;       // the largest damping ratio of any cell (b1 plus the quadratic's)
};

/// Runs the bar to the scene's end (2 L / c) with the problem's own probe, watching the
/// mass-weighted mean x velocity of the nodes within 0.01 of x = L / 2 until the pulse has
/// passed there (its reflection comes back at 1.5 L / c).
BarMeasures run_bar(const std::string& text) {
  const DynamicsScene scene = parse_dynamics_scene(text, "test scene");
  ExplicitSimulation model = dynamics_simulation(scene, ensemble_runs(scene.meshes).front());
  CentralDifference& run = *model.run;
  DynamicsProbe probe(scene, *scene.problem, model.bodies, run, scene.output_every);
  std::vector<int> middle;
  for (int i = 0; i < run.dofs().num_nodes(); ++i)
    if (std::abs(run.node_position(i).x() - 0.5) < 0.01) middle.push_back(i);
  const double window =
      0.5 / scene.dilatational_speed() + 1.5 * std::stod(scene.setting("pulse.duration"));
  BarMeasures m;
  for (long s = 0; s < model.steps; ++s) {
    const StepRecord& r = run.step();
    probe.observe();
    double p = 0.0, mass = 0.0;
    for (int i : middle)
      p += run.node_masses()[i] * run.velocity()[2 * i], mass += run.node_masses()[i];
    if (r.time < window) m.peak = std::max(m.peak, p / mass);  // amplitude 1 m/s
    if (model.bulk) m.max_xi = std::max(m.max_xi, model.bulk->max_damping_ratio());
  }
  m.speed_error = probe.measures().wave_speed_error;
  m.dissipated = run.record().bulk_viscosity_dissipation / run.record().input_energy();
  m.balance = probe.measures().max_energy_balance_error;
  return m;
}

TEST(BulkViscosity, SceneKeysAreOffByDefault) {
  const DynamicsScene off = parse_dynamics_scene(wave_bar(0.9, ""), "test");
  EXPECT_FALSE(off.bulk_viscosity.active());
  EXPECT_EQ(off.setting("bulk_viscosity.linear"), "0");
  EXPECT_EQ(off.setting("bulk_viscosity.quadratic"), "0");
  const DynamicsScene on =
      parse_dynamics_scene(wave_bar(0.9, R"("bulk_viscosity": {"linear": 0.06})"), "test");
  EXPECT_EQ(on.bulk_viscosity.linear, 0.06);
  EXPECT_EQ(on.bulk_viscosity.quadratic, 0.0);
  // With cells that turn, the rate of the current volume.
  EXPECT_TRUE(parse_dynamics_scene(wave_bar(0.9, R"("kinematics": "corotational",
    "bulk_viscosity": {"linear": 0.06})"),
                                   "test")
                  .corotational);
  EXPECT_THROW(parse_dynamics_scene(wave_bar(0.9, R"("bulk_viscosity": {"quadratic": -1})"), "t"),
               InputError);
}

TEST(BulkViscosity, WaveBarOvershootFallsAndTheSpeedStays) {
  const std::string on = R"("bulk_viscosity": {"linear": 0.06, "quadratic": 1.2})";
  for (double duration : {0.1, 0.3, 0.9}) {  // a rise over 2.7, 8 and 24 cells
    const BarMeasures a = run_bar(wave_bar(duration, "")), b = run_bar(wave_bar(duration, on));
    std::printf(
        "wave bar, hex, rollers, pulse %.1f L/c: overshoot %.2f%% off, %.2f%% on (ratio %.1f); "
        "speed error %+.3f%% off, %+.3f%% on (%+.3f%% apart); bulk viscosity took %.2f%% of the "
        "input, largest xi %.6f; balance %.1e / %.1e\n",
        duration, 100 * (a.peak - 1), 100 * (b.peak - 1), (a.peak - 1) / (b.peak - 1),
        100 * a.speed_error, 100 * b.speed_error,
        100 * ((1 + b.speed_error) / (1 + a.speed_error) - 1), 100 * b.dissipated, b.max_xi,
        a.balance, b.balance);
    EXPECT_LT(b.balance, 1e-12);
    if (duration != 0.3) continue;  // the short pulse is printed only (its plateau is eroded)
    EXPECT_GT(a.peak - 1, 0.02);    // a visible overshoot without
    EXPECT_LT(b.peak - 1, 0.5 * (a.peak - 1));  // at least halved with
    EXPECT_LT(std::abs((1 + b.speed_error) / (1 + a.speed_error) - 1), 0.005);
    EXPECT_LT(std::abs(b.speed_error), 0.005);
  }
}

}  // namespace
}  // namespace vorodg
