// Explicit central differences (dynamics/CentralDifference) with lumped masses:
//   - a free rcp body in uniform motion plus a rigid spin, alone and with a small random elastic
//     vibration (fixed seed), for 1e4 steps: linear momentum constant to 1e-12 relative, the
//     discrete energy balance to 1e-4 (measured about 1e-12); for the rigid motion alone also
//     the energy with 1/2 v.M v (1e-4) and the angular momentum (1e-11; measured 1.5e-12);
//   - a wave bar (1 x 0.05 m, steel, quad / hex / rcp, plane stress and plane strain): a smooth
//     velocity pulse at the left end, the far end free. The arrival time (the far end's mean
//     velocity reaching the incident amplitude, half its doubled plateau, less the input's own
//     half-rise time) matches L / c within 1%, where c is the dilatational speed
//     sqrt(E / (rho (1 - nu^2))) (stress) or sqrt(E (1 - nu) / (rho (1 + nu) (1 - 2 nu))) (strain)
//     with rollers on the long sides (uniaxial strain), and the bar speed sqrt(E / rho) (stress)
//     or sqrt(E / (rho (1 - nu^2))) (strain) with the long sides free (uniaxial stress); the
//     energy balance closes to 1e-3 of the input energy over 1e4 steps;
//   - damping, a body force, an external force and prescribed velocities together: the balance
//     closes to 1e-10, dissipation grows, fixed DOFs do not move;
//   - a split of every node (remap to the fully discontinuous map) and the merge back keep the
//     linear momentum, and the split keeps the kinetic and elastic energies; after a partial
//     split the reassembled internal force and energy equal a fresh compute's bit for bit;
//   - 1 and 2 threads give bit-identical states and records.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>

#include "core/util/Errors.hpp"
#include "core/util/Random.hpp"
#include "dynamics/GlobalTimeStep.hpp"
#include "support/DynamicsModel.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;

/// 0.9 x the Lanczos critical step of the model on the continuous map.
double lanczos_step(const DynamicsModel& model) {
  const SplitDofMap dofs = SplitDofMap::continuous(model.mesh);
  InternalForce force(model.mesh, model.matrices);
  return GlobalTimeStep(force, dofs, model.mass.node_masses(dofs), model.limit).step(0.9);
}

/// Initial velocity of a rigid motion: translation V plus spin omega about the centroid.
Eigen::VectorXd rigid_velocity(const CentralDifference& run, const Eigen::Vector2d& V, double omega,
                               const Point& centre) {
  Eigen::VectorXd v(run.dofs().num_dofs());
  for (int i = 0; i < run.dofs().num_nodes(); ++i) {
    const Point r = run.node_position(i) - centre;
    v.segment<2>(2 * i) = V + omega * Eigen::Vector2d(-r.y(), r.x());
  }
  return v;
}

TEST(CentralDifference, FreeBodyKeepsMomentumAndEnergy) {
  const DynamicsModel model(mesh_spec(MeshFamily::rcp, Rectangle(0, 0, 1, 1), 0.05),
                            IsotropicElasticity(1.0, 0.3, PlaneModel::stress), 1.0);
  for (double vibration : {0.0, 1e-4}) {
    auto run = model.integrator_with(lanczos_step(model));
    const int n = run->dofs().num_dofs();
    run->initialize(random_vector(n, vibration, 3),
                    rigid_velocity(*run, {0.01, 0.005}, 0.01, {0.5, 0.5}));
    const StepRecord start = run->record();
    double p_drift = 0.0, l_drift = 0.0, e_drift = 0.0, e_integer = 0.0;
    for (int s = 0; s < 10000; ++s) {
      const StepRecord& r = run->step();
      p_drift = std::max(p_drift, (r.momentum - start.momentum).norm() / start.momentum.norm());
      l_drift = std::max(l_drift, std::abs(r.angular_momentum - start.angular_momentum) /
                                      std::abs(start.angular_momentum));
      e_drift = std::max(e_drift, std::abs(r.balance() - r.initial_balance) / r.input_energy());
      e_integer = std::max(
          e_integer, std::abs(r.balance_integer() - r.initial_balance_integer) / r.input_energy());
    }
    std::printf(
        "free body, %d cells, vibration %.0e, 1e4 steps: momentum drift %.2e, angular "
        "momentum drift %.2e, energy drift %.2e (with 1/2 v.M v: %.2e)\n",
        model.mesh.num_cells(), vibration, p_drift, l_drift, e_drift, e_integer);
    EXPECT_LT(p_drift, 1e-12);
    EXPECT_LT(e_drift, 1e-4);
    if (vibration == 0.0) {  // a rigid motion: no strain, so 1/2 v.M v is exact too
      EXPECT_LT(e_integer, 1e-4);
      EXPECT_LT(l_drift, 1e-11);
    }
  }
}

struct BarCase {
  const char* mesh;
  MeshFamily family;
  PlaneModel model;
  bool rollers;
  bool mean_dilation;
};

/// Expected wave speed: dilatational with rollers (uniaxial strain), bar speed without.
double wave_speed(const IsotropicElasticity& m, double rho, bool rollers) {
  const double E = m.E(), nu = m.nu();
  if (m.model() == PlaneModel::stress)
    return rollers ? std::sqrt(E / (rho * (1 - nu * nu))) : std::sqrt(E / rho);
  return rollers ? std::sqrt(E * (1 - nu) / (rho * (1 + nu) * (1 - 2 * nu)))
                 : std::sqrt(E / (rho * (1 - nu * nu)));
}

/// Smooth pulse: a (1 - cos) rise over tr, a hold of tr, a (1 + cos) fall over tr.
double pulse(double t, double amplitude, double tr) {
  constexpr double pi = std::numbers::pi;
  if (t <= 0.0 || t >= 3 * tr) return 0.0;
  if (t < tr) return amplitude * 0.5 * (1 - std::cos(pi * t / tr));
  if (t < 2 * tr) return amplitude;
  return amplitude * 0.5 * (1 + std::cos(pi * (t - 2 * tr) / tr));
}

TEST(CentralDifference, WaveBarArrivalAndEnergy) {
  const double E = 200e9, nu = 0.3, rho = 7800.0, L = 1.0, amplitude = 1.0;
  const BarCase cases[] = {
      {"quad", MeshFamily::quad, PlaneModel::stress, true, false},
      {"quad", MeshFamily::quad, PlaneModel::strain, true, false},
      {"hex", MeshFamily::hex, PlaneModel::stress, true, false},
      {"hex", MeshFamily::hex, PlaneModel::strain, true, false},
      {"rcp", MeshFamily::rcp, PlaneModel::stress, true, false},
      {"rcp", MeshFamily::rcp, PlaneModel::strain, true, false},
      {"rcp", MeshFamily::rcp, PlaneModel::strain, true, true},
      {"quad", MeshFamily::quad, PlaneModel::stress, false, false},
      {"quad", MeshFamily::quad, PlaneModel::strain, false, false},
      {"hex", MeshFamily::hex, PlaneModel::stress, false, false},
      {"hex", MeshFamily::hex, PlaneModel::strain, false, false},
      {"rcp", MeshFamily::rcp, PlaneModel::stress, false, false},
      {"rcp", MeshFamily::rcp, PlaneModel::strain, false, false},
  };
  for (const BarCase& k : cases) {
    const IsotropicElasticity material(E, nu, k.model);
    const DynamicsModel model(mesh_spec(k.family, Rectangle(0, 0, L, 0.05), 0.0125), material, rho,
                              k.mean_dilation);
    const double c = wave_speed(material, rho, k.rollers), tr = 0.3 * L / c;
    auto run = model.integrator_with(lanczos_step(model));
    run->add_velocity_boundary({model.mesh.side_vertices(Side::left), 0,
                                [&](double t) { return pulse(t, amplitude, tr); }});
    if (k.rollers)
      for (Side s : {Side::bottom, Side::top})
        run->add_velocity_boundary({model.mesh.side_vertices(s), 1, [](double) { return 0.0; }});
    const int n = run->dofs().num_dofs();
    run->initialize(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n));
    std::vector<int> far;
    for (int v : model.mesh.side_vertices(Side::right))
      for (int node : run->dofs().vertex_nodes(v)) far.push_back(node);
    auto far_velocity = [&] {
      double p = 0.0, m = 0.0;
      for (int node : far) p += run->node_masses()[node] * run->velocity()[2 * node];
      for (int node : far) m += run->node_masses()[node];
      return p / m;
    };
    double arrival = -1.0, previous = 0.0, drift = 0.0, drift_integer = 0.0, input = 0.0;
    for (int s = 0; s < 10000; ++s) {
      const StepRecord& r = run->step();
      const double now = far_velocity();
      if (arrival < 0 && now >= amplitude)  // the incident amplitude: half the doubled plateau
        arrival = r.time - run->dt() * (now - amplitude) / (now - previous) - 0.5 * tr;
      previous = now;
      input = std::max(input, r.input_energy());
      drift = std::max(drift, std::abs(r.balance() - r.initial_balance));
      drift_integer =
          std::max(drift_integer, std::abs(r.balance_integer() - r.initial_balance_integer));
    }
    const double error = arrival / (L / c) - 1.0;
    std::printf(
        "%-4s %-12s %-7s%s %4d cells, dt %.3e: arrival %.5e s, L/c %.5e s, error %+.4f; "
        "energy balance / input over 1e4 steps %.2e (with 1/2 v.M v: %.2e)\n",
        k.mesh, k.model == PlaneModel::stress ? "plane-stress" : "plane-strain",
        k.rollers ? "rollers" : "free", k.mean_dilation ? " mean-dilation" : "",
        model.mesh.num_cells(), run->dt(), arrival, L / c, error, drift / input,
        drift_integer / input);
    EXPECT_LT(std::abs(error), 0.01) << k.mesh;
    EXPECT_LT(drift / input, 1e-3) << k.mesh;
  }
}

TEST(CentralDifference, BalanceClosesWithDampingLoadsAndSupports) {
  const DynamicsModel model(mesh_spec(MeshFamily::rcp, Rectangle(0, 0, 1, 1), 0.1),
                            IsotropicElasticity(1.0, 0.25, PlaneModel::strain), 1.0);
  DynamicsOptions options;
  options.damping = 0.3;
  auto run = model.integrator_with(model.limit.step(), options);
  const std::vector<int> left = model.mesh.side_vertices(Side::left);
  const std::vector<int> right = model.mesh.side_vertices(Side::right);
  run->add_velocity_boundary({left, 0, [](double t) { return 0.01 * std::sin(3.0 * t); }});
  run->add_velocity_boundary({left, 1, [](double) { return 0.0; }});
  run->set_body_force(
      [](double t) { return Eigen::Vector2d(0.0, -0.02 * (1 + 0.5 * std::sin(t))); });
  std::vector<int> pulled;
  run->set_external_force([&](double t, const Eigen::VectorXd&, Eigen::VectorXd& f) {
    for (int node : pulled) f[2 * node] += 1e-3 * std::cos(2.0 * t);
  });
  for (int v : right)
    for (int node : run->dofs().vertex_nodes(v)) pulled.push_back(node);
  const int n = run->dofs().num_dofs();
  run->initialize(random_vector(n, 1e-3, 8), Eigen::VectorXd::Zero(n));
  double drift = 0.0, dissipated = 0.0;
  for (int s = 0; s < 2000; ++s) {
    const StepRecord& r = run->step();
    drift = std::max(drift, std::abs(r.balance() - r.initial_balance) / r.input_energy());
    ASSERT_GE(r.damping_dissipation, dissipated);
    dissipated = r.damping_dissipation;
  }
  const StepRecord& r = run->record();
  std::printf(
      "damped, loaded, supported: balance drift %.2e; external %.3e, reaction %.3e, "
      "dissipated %.3e, kinetic %.3e, elastic %.3e\n",
      drift, r.external_work, r.reaction_work, r.damping_dissipation, r.kinetic, r.elastic);
  EXPECT_LT(drift, 1e-10);
  EXPECT_GT(r.damping_dissipation, 0.0);
  EXPECT_NE(r.reaction_work, 0.0);
  EXPECT_NE(r.external_work, 0.0);
  const Eigen::VectorXd u0 = random_vector(n, 1e-3, 8);
  for (int v : left)
    for (int node : run->dofs().vertex_nodes(v))
      EXPECT_EQ(run->displacement()[2 * node + 1], u0[2 * node + 1]);
  EXPECT_THROW(run->add_velocity_boundary({left, 1, [](double) { return 0.0; }}), InputError);
}

TEST(CentralDifference, SplitAndMergeKeepMomentum) {
  const DynamicsModel model(mesh_spec(MeshFamily::rcp, Rectangle(0, 0, 1, 1), 0.1),
                            IsotropicElasticity(1.0, 0.3, PlaneModel::stress), 1.0);
  auto run = model.integrator_with(model.limit.step());
  const int n = run->dofs().num_dofs();
  run->initialize(random_vector(n, 1e-3, 4), random_vector(n, 1e-2, 5));
  for (int s = 0; s < 50; ++s) run->step();
  const StepRecord before = run->record();
  run->remap(SplitDofMap::discontinuous(model.mesh));
  const StepRecord split = run->record();
  EXPECT_EQ(run->dofs().num_nodes(), model.mass.num_pairs());
  EXPECT_LT((split.momentum - before.momentum).norm(), 1e-14 * before.momentum.norm());
  EXPECT_NEAR(split.kinetic, before.kinetic, 1e-14 * before.kinetic);
  EXPECT_NEAR(split.elastic, before.elastic, 1e-14 * before.elastic);
  for (int s = 0; s < 100; ++s) run->step();
  const StepRecord apart = run->record();
  EXPECT_LT((apart.momentum - split.momentum).norm(), 1e-13 * split.momentum.norm());
  EXPECT_LT(std::abs(apart.balance() - apart.initial_balance), 1e-12 * apart.input_energy());
  run->remap(SplitDofMap::continuous(model.mesh));
  EXPECT_LT((run->record().momentum - apart.momentum).norm(), 1e-13 * apart.momentum.norm());
  EXPECT_EQ(run->dofs().num_nodes(), model.mesh.num_vertices());
}

TEST(CentralDifference, ASplitReassemblesTheForceACopyWouldCompute) {
  // After a split the cells' displacements are copies, so InternalForce::reassemble (what the
  // remap uses) must give exactly the force and energy a fresh compute gives.
  const DynamicsModel model(mesh_spec(MeshFamily::rcp, Rectangle(0, 0, 1, 1), 0.1),
                            IsotropicElasticity(1.0, 0.3, PlaneModel::stress), 1.0);
  auto run = model.integrator_with(model.limit.step());
  const int n = run->dofs().num_dofs();
  run->initialize(random_vector(n, 1e-3, 4), random_vector(n, 1e-2, 5));
  for (int s = 0; s < 20; ++s) run->step();
  std::vector<char> connected(model.mesh.num_edges(), 1);
  for (int e = 0; e < model.mesh.num_edges(); e += 3) connected[e] = 0;
  run->remap(SplitDofMap(model.mesh, connected));
  InternalForce fresh(model.mesh, model.matrices);
  Eigen::VectorXd f;
  const double energy = fresh.compute(run->dofs(), run->displacement(), f, 1);
  EXPECT_EQ(run->record().elastic, energy);
  EXPECT_TRUE(run->internal_force() == f);  // bit for bit
}

TEST(CentralDifference, ALocalSplitGivesTheRemapsStatePairForPair) {
  // Two runs from one state: one remapped onto the map built from scratch, one split in place
  // (appended nodes). Read per (cell, vertex) pair, the state must be the same bits, and it
  // must stay so over steps with further batches of cracks; the record's sums add the nodes in
  // another order, so they agree to round-off.
  const DynamicsModel model(mesh_spec(MeshFamily::rcp, Rectangle(0, 0, 1, 1), 0.1),
                            IsotropicElasticity(1.0, 0.3, PlaneModel::stress), 1.0);
  auto full = model.integrator_with(model.limit.step());
  auto local = model.integrator_with(model.limit.step());
  const int n = full->dofs().num_dofs();
  for (auto* run : {full.get(), local.get()}) {
    run->initialize(random_vector(n, 1e-3, 4), random_vector(n, 1e-2, 5));
    run->step();
  }
  const auto same_per_pair = [&](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    for (int c = 0; c < model.mesh.num_cells(); ++c)
      for (int k = 0; k < model.mesh.cell_size(c); ++k) {
        const int i = full->dofs().node(c, k), j = local->dofs().node(c, k);
        if (a.segment<2>(2 * i) != b.segment<2>(2 * j)) return false;
      }
    return true;
  };
  Random random(12);
  std::vector<char> connected(model.mesh.num_edges(), 1);
  for (int batch = 0; batch < 6; ++batch) {
    std::vector<int> edges;
    for (int e = 0; e < model.mesh.num_edges(); ++e)
      if (connected[e] && !model.mesh.edge(e).on_boundary() && random.uniform() < 0.1)
        edges.push_back(e), connected[e] = 0;
    full->remap(SplitDofMap(model.mesh, connected));
    local->disconnect(connected, edges);
    ASSERT_EQ(full->dofs().num_nodes(), local->dofs().num_nodes());
    EXPECT_TRUE(same_per_pair(full->displacement(), local->displacement())) << batch;
    EXPECT_TRUE(same_per_pair(full->velocity(), local->velocity())) << batch;
    EXPECT_TRUE(same_per_pair(full->acceleration(), local->acceleration())) << batch;
    EXPECT_TRUE(same_per_pair(full->internal_force(), local->internal_force())) << batch;
    const StepRecord &a = full->record(), &b = local->record();
    EXPECT_EQ(a.elastic, b.elastic);
    EXPECT_NEAR(a.kinetic, b.kinetic, 1e-13 * a.kinetic);
    EXPECT_NEAR(a.remap_energy, b.remap_energy, 1e-13 * a.kinetic);
    for (int s = 0; s < 5; ++s) full->step(), local->step();
  }
  EXPECT_TRUE(same_per_pair(full->displacement(), local->displacement()));
  EXPECT_GT(local->dofs().num_nodes(), model.mesh.num_vertices() + 40);  // it did split
}

TEST(CentralDifference, OneAndTwoThreadsGiveTheSameBits) {
  const DynamicsModel model(mesh_spec(MeshFamily::rcp, Rectangle(0, 0, 1, 1), 0.025),
                            IsotropicElasticity(1.0, 0.3, PlaneModel::strain), 1.0, true);
  auto run_with = [&](int threads) {
    DynamicsOptions options;
    options.threads = threads;
    options.damping = 0.1;
    auto run = model.integrator_with(model.limit.step(), options);
    run->add_velocity_boundary(
        {model.mesh.side_vertices(Side::left), 0, [](double t) { return 0.01 * std::sin(t); }});
    run->set_body_force([](double) { return Eigen::Vector2d(0.0, -0.01); });
    const int n = run->dofs().num_dofs();
    run->initialize(random_vector(n, 1e-3, 6), random_vector(n, 1e-3, 7));
    for (int s = 0; s < 100; ++s) run->step();
    return run;
  };
  const auto one = run_with(1), two = run_with(2);
  ASSERT_GT(one->dofs().num_nodes(), 2 * OrderedSum::kChunk);
  auto same = [](const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
  };
  EXPECT_TRUE(same(one->displacement(), two->displacement()));
  EXPECT_TRUE(same(one->velocity(), two->velocity()));
  EXPECT_TRUE(same(one->acceleration(), two->acceleration()));
  EXPECT_TRUE(same(one->reaction(), two->reaction()));
  const StepRecord &a = one->record(), &b = two->record();
  EXPECT_EQ(a.kinetic, b.kinetic);
  EXPECT_EQ(a.elastic, b.elastic);
  EXPECT_EQ(a.external_work, b.external_work);
  EXPECT_EQ(a.reaction_work, b.reaction_work);
  EXPECT_EQ(a.damping_dissipation, b.damping_dissipation);
  EXPECT_EQ(a.momentum, b.momentum);
  EXPECT_EQ(a.angular_momentum, b.angular_momentum);
}

}  // namespace
}  // namespace vorodg
