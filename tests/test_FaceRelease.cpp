// Release of broken crack faces (CohesiveForces::releasable / release, DynamicFracture,
// SurfaceCells::release). A face may let go once it is fully broken, open at both points and its
// ends are apart by its length; then its forces stop, its energies stay frozen at zero, and
// surface contact takes over between its two cells.
//   - Unit: on a strip of quad cells, one interior edge is opened along its normal past the
//     critical opening and then by its length: only then is it releasable; closing it (g_n < 0)
//     or a shear with the ends apart by less than the length is not; after release, an
//     evaluation at an overclosure adds no force, books no work and stores nothing, and the
//     dissipated energy stays G x length.
//   - Two cells, one pulled away from the other, crack at their common edge and fly apart; the
//     right one bounces off a rigid plane and comes back. The face lets go on the way out, and
//     surface contact stops the returning cell: it pushes the left cell away, the overlap stays
//     below 2 % of h, the discrete energy balance closes to 1e-9, and the gap between the law's
//     closed forms and the booked cohesive work does not move after the release.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/util/Errors.hpp"
#include "dynamics/ContactForces.hpp"
#include "dynamics/DynamicFracture.hpp"
#include "support/DynamicsModel.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;

constexpr double kE = 30e9, kDensity = 2400.0, kStrength = 3e6, kToughness = 1.0;
constexpr double kH = 0.01;  // cell size, m

CohesiveLaw law() {
  return CohesiveLaw(CohesiveParameters{kStrength, kToughness, 1.0, "linear", 10 * kE / kH});
}

/// Displacements that move cell1 of edge e rigidly by `shift`, everything else at rest.
Eigen::VectorXd moved(const PolygonMesh& mesh, const SplitDofMap& dofs, int e, const Point& shift) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(2 * dofs.num_nodes());
  const int c = mesh.edge(e).cell1;
  for (int k = 0; k < mesh.cell_size(c); ++k) u.segment<2>(2 * dofs.node(c, k)) = shift;
  return u;
}

TEST(FaceRelease, OnlyABrokenOpenFaceApartByItsLengthMayLetGo) {
  const DynamicsModel m(mesh_spec(MeshFamily::quad, Rectangle(0, 0, 3 * kH, kH), kH),
                        IsotropicElasticity(kE, 0.2, PlaneModel::strain), kDensity);
  const CohesiveLaw cohesive_law = law();
  CohesiveForces faces(m.mesh, cohesive_law);
  int e = -1;
  for (int k = 0; k < m.mesh.num_edges() && e < 0; ++k)
    if (m.mesh.edge(k).cell1 >= 0) e = k;
  faces.add_edge(e);
  const SplitDofMap dofs = SplitDofMap::discontinuous(m.mesh);
  faces.bind(dofs);
  const double length = m.mesh.edge_length(e), critical = cohesive_law.critical_opening();
  const Point d = m.mesh.vertex(m.mesh.edge(e).v1) - m.mesh.vertex(m.mesh.edge(e).v0);
  const Point t = d / length, n(t.y(), -t.x());
  Eigen::VectorXd f = Eigen::VectorXd::Zero(2 * dofs.num_nodes());
  const auto evaluate_at = [&](const Point& shift) {
    f.setZero();
    faces.evaluate(moved(m.mesh, dofs, e, shift), f);
  };
  // Open along the normal in small steps, so that the law's history follows the path.
  for (int s = 1; s <= 20; ++s) evaluate_at((0.1 * s * critical) * n);
  EXPECT_FALSE(faces.releasable(e)) << "broken but open by 2 delta_c only, not by its length";
  EXPECT_THROW(faces.release(e), InputError);
  evaluate_at(0.5 * length * n);
  EXPECT_FALSE(faces.releasable(e));
  evaluate_at(1.2 * length * t - 1e-3 * length * n);  // apart, but overclosed along n
  EXPECT_FALSE(faces.releasable(e));
  evaluate_at(0.9 * length * t + 1e-3 * length * n);  // open, but the ends are too close
  EXPECT_FALSE(faces.releasable(e));
  evaluate_at(1.2 * length * n);
  ASSERT_TRUE(faces.broken(e));
  ASSERT_TRUE(faces.releasable(e));
  const double work = faces.work();
  EXPECT_EQ(faces.stored_energy(), 0.0);
  faces.release(e);
  EXPECT_FALSE(faces.releasable(e));
  ASSERT_EQ(faces.released_edges(), std::vector<int>{e});
  evaluate_at(-0.01 * length * n);  // overclosed: the penalty would push back, were it bound
  EXPECT_EQ(f.norm(), 0.0);
  EXPECT_EQ(faces.work(), work);
  EXPECT_EQ(faces.stored_energy(), 0.0);
  EXPECT_NEAR(faces.dissipated_energy(e), kToughness * length, 1e-12 * kToughness * length);
}

TEST(FaceRelease, ReleasedCellsMeetThroughSurfaceContact) {
  const DynamicsModel m(mesh_spec(MeshFamily::quad, Rectangle(0, 0, 2 * kH, kH), kH),
                        IsotropicElasticity(kE, 0.2, PlaneModel::strain), kDensity);
  ASSERT_EQ(m.mesh.num_cells(), 2);
  const CohesiveLaw cohesive_law = law();
  const std::vector<char> every_edge(m.mesh.num_edges(), 1);
  auto run = m.integrator_with(
      CohesiveForces::stable_step(m.limit, m.mesh, m.mass, cohesive_law, every_edge, 0.9));
  ContactForces contact(m.mesh, PenaltyContact());
  contact.add_plane(Point(4 * kH, 0.0), Point(-1.0, 0.0));  // a wall one cell beyond x = 3h
  run->set_contact(contact);
  CohesiveForces faces(m.mesh, cohesive_law);
  const MohrCoulomb criterion(MohrCoulombParameters{kStrength, 0.75, kStrength});
  CrackInsertion insertion(m.mesh, m.integrator, criterion, every_edge);
  DynamicFracture fracture(m.mesh, *run, faces, insertion, &contact);
  // The right cell is pulled away at 10 m/s, and a little upwards, so that it comes back a
  // fifth of a cell higher: squares meeting level would touch corner on edge, at zero depth.
  const double speed = 10.0;
  Eigen::VectorXd v0 = Eigen::VectorXd::Zero(run->dofs().num_dofs());
  for (int i = 0; i < run->dofs().num_nodes(); ++i)
    if (run->node_position(i).x() > 1.5 * kH) v0.segment<2>(2 * i) = Point(speed, 0.05 * speed);
  run->initialize(Eigen::VectorXd::Zero(v0.size()), v0);
  double balance = 0.0, law_balance = 0.0, depth = 0.0;
  double law_gap_at_release = NAN;  // cohesive work + the law's closed forms, when it let go
  double released_at = -1.0, wall_at = -1.0, met_at = -1.0;
  while (run->time() < 10 * kH / speed) {
    fracture.step(1);
    const StepRecord& r = run->record();
    balance = std::max(balance, std::abs(r.balance() - r.initial_balance) / r.input_energy());
    const double law_gap = r.cohesive_work + faces.dissipated_energy() + faces.stored_energy();
    law_balance = std::max(law_balance, std::abs(law_gap) / r.input_energy());
    depth = std::max(depth, contact.surface_report().max_depth);
    if (released_at < 0 && !faces.released_edges().empty()) {
      released_at = run->time();
      law_gap_at_release = law_gap;
    }
    if (wall_at < 0 && contact.plane_report().contacts > 0) wall_at = run->time();
    if (met_at < 0 && contact.surface_report().contacts > 0) met_at = run->time();
  }
  // The left cell's momentum (its nodes are its own once the edge has split): it started at
  // rest, and only the returning right cell can push it left.
  double x0 = 0.0;
  for (int v : m.mesh.cell_vertices(0)) x0 += m.mesh.vertex(v).x() / m.mesh.cell_size(0);
  const int left_cell = x0 < kH ? 0 : 1;
  double left = 0.0, mass = 0.0;
  for (int k = 0; k < m.mesh.cell_size(left_cell); ++k) {
    const int i = run->dofs().node(left_cell, k);
    left += run->node_masses()[i] * run->velocity()[2 * i];
    mass += run->node_masses()[i];
  }
  std::printf(
      "two cells: released at %.3g ms, wall at %.3g ms, met at %.3g ms; overlap / h %.2e, balance "
      "%.2e, law balance %.2e, left cell's velocity %.3g m/s\n",
      1e3 * released_at, 1e3 * wall_at, 1e3 * met_at, depth / kH, balance, law_balance,
      left / mass);
  ASSERT_EQ(faces.released_edges().size(), 1u);
  EXPECT_GT(released_at, 0.0);
  EXPECT_GT(wall_at, released_at);
  EXPECT_GT(met_at, wall_at);
  EXPECT_LT(left / mass, -0.2 * speed) << "the returning cell should have pushed the left away";
  EXPECT_LT(depth, 0.02 * kH);
  EXPECT_LT(balance, 1e-9);  // measured 1.8e-10: round-off of the stiff springs
  // The law's closed forms against the booked work: the step's error at the law's kinks, all
  // of it before the release (measured 1.5e-3); after it, nothing changes.
  EXPECT_LT(law_balance, 1e-2);
  const StepRecord& end = run->record();
  EXPECT_NEAR(end.cohesive_work + faces.dissipated_energy() + faces.stored_energy(),
              law_gap_at_release, 1e-14 * end.input_energy());
}

}  // namespace
}  // namespace vorodg
