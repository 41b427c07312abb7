// Contact in the integrator (dynamics/ContactForces with CentralDifference):
//   - two rcp bodies in one mesh thrown at each other (an eccentric impact): total linear momentum
//     kept to 1e-12 of sum m|v| through the contact (measured ~1e-15), the energy balance with
//     the contact work closes to 1e-11 of the input (measured 6e-13), the contact happens and
//     ends, and every penetration stays below 1% of h_avg at the default penalty;
//   - a body bounced off a rigid plane with contact damping: the balance closes to 1e-12, the
//     plane takes energy (contact work < 0 after the bounce), the rebound is slower;
//   - a free body with contact on and nothing to touch: momentum to 1e-12, zero contact work;
//   - contact set after initialize(), or evaluated before bind(), is refused.
#include "dynamics/ContactForces.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "core/element/ElasticityIntegrator.hpp"
#include "core/element/ElementTable.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Errors.hpp"
#include "dynamics/CentralDifference.hpp"
#include "dynamics/GlobalTimeStep.hpp"
#include "dynamics/LumpedMass.hpp"
#include "dynamics/StableTimeStep.hpp"

namespace vorodg {
namespace {

PolygonMesh rcp(const Rectangle& domain, double d, std::uint64_t seed) {
  MeshSpec spec;
  spec.domain = domain;
  spec.size = d;
  spec.seed = seed;
  return generate_mesh(spec).mesh;
}

/// The bodies' meshes joined into one (no shared vertex); `first` gets each body's first cell.
PolygonMesh join(const std::vector<PolygonMesh>& bodies, std::vector<int>& first) {
  std::vector<Point> vertices;
  std::vector<int> offsets{0}, loops;
  Point lo = bodies[0].domain().lo(), hi = bodies[0].domain().hi();
  for (const PolygonMesh& b : bodies) {
    first.push_back(static_cast<int>(offsets.size()) - 1);
    const int shift = static_cast<int>(vertices.size());
    vertices.insert(vertices.end(), b.vertices().begin(), b.vertices().end());
    for (int v : b.cell_vertex_list()) loops.push_back(v + shift);
    for (int c = 0; c < b.num_cells(); ++c) offsets.push_back(offsets.back() + b.cell_size(c));
    lo = lo.cwiseMin(b.domain().lo()), hi = hi.cwiseMax(b.domain().hi());
  }
  return PolygonMesh(Rectangle(lo.x(), lo.y(), hi.x(), hi.y()), vertices, offsets, loops);
}

/// Everything a run needs, on one mesh (not movable: the table refers to the mesh).
struct Model {
  PolygonMesh mesh;
  ElementTable table;
  LumpedMass mass;
  ElasticityIntegrator integrator;
  StableTimeStep bound;
  double dt = 0.0;

  explicit Model(PolygonMesh m)
      : mesh(std::move(m)),
        table(mesh, ElementOptions{}),
        mass(table, 1.0),
        integrator(table, IsotropicElasticity(1.0, 0.3, PlaneModel::stress), false),
        bound(mesh, integrator.all_cell_matrices(1), mass) {
    InternalForce force(mesh, integrator.all_cell_matrices(1));
    const SplitDofMap dofs = SplitDofMap::continuous(mesh);
    dt = GlobalTimeStep(force, dofs, mass.node_masses(dofs), bound).step(0.9);
  }
  std::unique_ptr<CentralDifference> run() const {
    return std::make_unique<CentralDifference>(mesh, mass,
                                               InternalForce(mesh, integrator.all_cell_matrices(1)),
                                               SplitDofMap::continuous(mesh), dt);
  }
};

/// Node velocities: body b (cells from first[b]) moves at velocity[b].
Eigen::VectorXd velocities(const CentralDifference& run, const PolygonMesh& mesh,
                           const std::vector<int>& first, const std::vector<Point>& velocity) {
  Eigen::VectorXd v(run.dofs().num_dofs());
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const int b = c >= first.back() ? static_cast<int>(first.size()) - 1 : 0;
    for (int k = 0; k < mesh.cell_size(c); ++k)
      v.segment<2>(2 * run.dofs().node(c, k)) = velocity[b];
  }
  return v;
}

double momentum_scale(const CentralDifference& run) {
  double s = 0.0;
  for (int i = 0; i < run.dofs().num_nodes(); ++i)
    s += run.node_masses()[i] * run.velocity().segment<2>(2 * i).norm();
  return s;
}

TEST(ContactForces, TwoBodiesKeepMomentumAndTheBalanceCloses) {
  std::vector<int> first;
  const Model model(join(
      {rcp(Rectangle(0, 0, 1, 0.5), 0.1, 3), rcp(Rectangle(1.01, 0.2, 1.61, 0.9), 0.1, 4)}, first));
  ContactForces contact(model.mesh, PenaltyContact());
  auto run = model.run();
  run->set_contact(contact);
  run->initialize(Eigen::VectorXd::Zero(run->dofs().num_dofs()),
                  velocities(*run, model.mesh, first, {Point(1e-3, 0), Point(-5e-4, 0)}));
  const StepRecord start = run->record();
  const double scale = momentum_scale(*run), h = std::sqrt(model.mesh.total_area() / first.back());
  double drift = 0.0, balance = 0.0, depth = 0.0;
  int contact_steps = 0;
  for (int s = 0; s < 1200; ++s) {
    const StepRecord& r = run->step();
    drift = std::max(drift, (r.momentum - start.momentum).norm() / scale);
    balance = std::max(balance, std::abs(r.balance() - r.initial_balance) / r.input_energy());
    depth = std::max(depth, contact.surface_report().max_depth);
    contact_steps += contact.surface_report().contacts > 0;
  }
  std::printf(
      "two bodies, %d cells, %d steps in contact: momentum drift %.2e, balance %.2e, depth / "
      "h_avg %.2e, contact work at the end %.3e of the kinetic energy\n",
      model.mesh.num_cells(), contact_steps, drift, balance, depth / h,
      run->record().contact_work / start.kinetic);
  EXPECT_GT(contact_steps, 10);
  EXPECT_EQ(contact.surface_report().contacts, 0) << "the bodies should have separated";
  EXPECT_EQ(contact.plane_report().contacts, 0);
  EXPECT_LT(drift, 1e-12);
  EXPECT_LT(balance, 1e-11);  // measured 6e-13: round-off of the stiff contact springs
  EXPECT_LT(depth, 0.01 * h);
}

TEST(ContactForces, DampedBounceOffAPlaneBalances) {
  std::vector<int> first;
  const Model model(join({rcp(Rectangle(0, 0, 1, 0.5), 0.1, 5)}, first));
  PenaltyParameters law;
  law.damping_ratio = 0.3;
  ContactForces contact(model.mesh, PenaltyContact(law));
  contact.add_plane(Point(0.5, -0.001), Point(0, 1));
  auto run = model.run();
  run->set_contact(contact);
  run->initialize(Eigen::VectorXd::Zero(run->dofs().num_dofs()),
                  velocities(*run, model.mesh, first, {Point(0, -1e-3)}));
  const StepRecord start = run->record();
  double balance = 0.0;
  for (int s = 0; s < 600; ++s) {
    const StepRecord& r = run->step();
    balance = std::max(balance, std::abs(r.balance() - r.initial_balance) / r.input_energy());
  }
  const StepRecord& end = run->record();
  const double rebound = end.momentum.y() / model.mass.total();
  std::printf(
      "damped bounce: balance %.2e, contact work %.3e of the kinetic energy, rebound %.4f "
      "of the impact speed\n",
      balance, end.contact_work / start.kinetic, rebound / 1e-3);
  EXPECT_EQ(contact.plane_report().contacts, 0) << "the body should have left the plane";
  EXPECT_LT(balance, 1e-12);
  EXPECT_LT(end.contact_work, -0.05 * start.kinetic);
  EXPECT_GT(rebound, 0.0);
  EXPECT_LT(rebound, 0.95e-3);
}

TEST(ContactForces, FreeBodyWithNothingToTouchKeepsMomentum) {
  std::vector<int> first;
  const Model model(join({rcp(Rectangle(0, 0, 1, 1), 0.1, 6)}, first));
  ContactForces contact(model.mesh, PenaltyContact());
  contact.add_plane(Point(10, 0), Point(-1, 0));  // far away: never reached
  auto run = model.run();
  run->set_contact(contact);
  Eigen::VectorXd v = velocities(*run, model.mesh, first, {Point(1e-2, 5e-3)});
  for (int i = 0; i < run->dofs().num_nodes(); ++i) {  // plus a spin about the centre
    const Point r = run->node_position(i) - Point(0.5, 0.5);
    v.segment<2>(2 * i) += 1e-2 * Point(-r.y(), r.x());
  }
  run->initialize(Eigen::VectorXd::Zero(run->dofs().num_dofs()), v);
  const StepRecord start = run->record();
  const double scale = momentum_scale(*run);
  double drift = 0.0;
  for (int s = 0; s < 2000; ++s) {
    const StepRecord& r = run->step();
    drift = std::max(drift, (r.momentum - start.momentum).norm() / scale);
    ASSERT_EQ(contact.surface_report().contacts + contact.plane_report().contacts, 0);
  }
  std::printf("free body with contact on: momentum drift %.2e over 2000 steps\n", drift);
  EXPECT_LT(drift, 1e-12);
  EXPECT_EQ(run->record().contact_work, 0.0);
}

TEST(ContactForces, MisuseIsRefused) {
  std::vector<int> first;
  const Model model(join({rcp(Rectangle(0, 0, 1, 1), 0.2, 7)}, first));
  ContactForces contact(model.mesh, PenaltyContact());
  Eigen::VectorXd f;
  EXPECT_THROW(contact.evaluate(Eigen::VectorXd::Zero(4), Eigen::VectorXd::Zero(4), 0.1, f),
               InputError);
  auto run = model.run();
  const int n = run->dofs().num_dofs();
  run->initialize(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n));
  EXPECT_THROW(run->set_contact(contact), InputError);
}

}  // namespace
}  // namespace vorodg
