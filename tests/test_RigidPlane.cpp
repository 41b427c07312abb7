// A rigid half-plane: a square pushed into it by d gets k d on each vertex below it, along the
// normal, with a fixed and with the mass-scaled stiffness, on a tilted plane too; a node shared
// by two surface cells is pushed once; bad planes are refused.
#include "dynamics/contact/RigidPlane.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/dofs/SplitDofMap.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

PolygonMesh unit_square() {
  return PolygonMesh(Rectangle(0, 0, 1, 1), {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1)},
                     {0, 4}, {0, 1, 2, 3});
}

PenaltyParameters fixed(double k) {
  PenaltyParameters p;
  p.stiffness = k;
  return p;
}

TEST(RigidPlane, SquarePushedIntoTheFloorGetsKTimesDepth) {
  const PolygonMesh mesh = unit_square();
  const SurfaceCells surface(mesh);
  const double k = 2.5e3, d = 0.01;
  RigidPlane floor(Point(0, 0), Point(0, 3), PenaltyContact(fixed(k)));  // normalized
  std::vector<Point> x = mesh.vertices();
  for (Point& p : x) p.y() -= d;
  PairState state;
  state.position = x;
  std::vector<Point> f(4, Point::Zero());
  const auto report = floor.add_forces(surface, state, f);
  EXPECT_EQ(report.contacts, 2);
  EXPECT_NEAR(report.max_depth, d, 1e-15);
  EXPECT_NEAR(report.potential, 2 * 0.5 * k * d * d, 1e-12);
  for (int i : {0, 1}) EXPECT_NEAR((f[i] - Point(0, k * d)).norm(), 0.0, 1e-12);
  for (int i : {2, 3}) EXPECT_EQ(f[i], Point::Zero());
}

TEST(RigidPlane, MassScaledStiffnessIsAlphaMOverDtSquared) {
  const PolygonMesh mesh = unit_square();
  const SurfaceCells surface(mesh);
  PenaltyParameters p;
  p.alpha = 0.3;
  RigidPlane floor(Point(0, 0), Point(0, 1), PenaltyContact(p));
  std::vector<Point> x = mesh.vertices();
  const std::vector<double> m{1.0, 2.0, 1.0, 1.0};
  x[0].y() = -0.02;
  x[1].y() = -0.01;
  PairState state;
  state.position = x;
  state.mass = m;
  state.dt = 1e-2;
  std::vector<Point> f(4, Point::Zero());
  floor.add_forces(surface, state, f);
  EXPECT_NEAR(f[0].y(), 0.3 * 1.0 / 1e-4 * 0.02, 1e-10);
  EXPECT_NEAR(f[1].y(), 0.3 * 2.0 / 1e-4 * 0.01, 1e-10);
  EXPECT_EQ(f[0].x(), 0.0);
}

TEST(RigidPlane, TiltedPlanePushesAlongItsNormal) {
  const PolygonMesh mesh = unit_square();
  const SurfaceCells surface(mesh);
  const Point n = Point(1, 2).normalized();
  RigidPlane wall(Point(0.5, 0.5), n, PenaltyContact(fixed(10.0)));
  PairState state;
  state.position = mesh.vertices();
  std::vector<Point> f(4, Point::Zero());
  const auto report = wall.add_forces(surface, state, f);
  for (int i = 0; i < 4; ++i) {
    const double gap = (mesh.vertex(i) - Point(0.5, 0.5)).dot(n);
    if (gap < 0) {
      EXPECT_NEAR((f[i] - 10.0 * -gap * n).norm(), 0.0, 1e-14);
    } else {
      EXPECT_EQ(f[i], Point::Zero());
    }
  }
  EXPECT_EQ(report.contacts, 2);  // (0, 0) and (1, 0) lie below the line; (0, 1) above
}

TEST(RigidPlane, NodeSharedByTwoSurfaceCellsIsPushedOnce) {
  // Two unit squares side by side: the middle bottom vertex is a pair of each.
  const PolygonMesh mesh(
      Rectangle(0, 0, 2, 1),
      {Point(0, 0), Point(1, 0), Point(2, 0), Point(2, 1), Point(1, 1), Point(0, 1)}, {0, 4, 8},
      {0, 1, 4, 5, 1, 2, 3, 4});
  const SurfaceCells surface(mesh);
  ASSERT_EQ(surface.size(), 2);
  const SplitDofMap dofs = SplitDofMap::continuous(mesh);
  const Eigen::VectorXd u = Eigen::VectorXd::Constant(dofs.num_dofs(), -0.1);  // all sink 0.1
  const auto x = pair_positions(mesh, dofs, u);
  const auto nodes = pair_nodes(mesh, dofs);
  const double k = 100.0;
  RigidPlane floor(Point(0, 0), Point(0, 1), PenaltyContact(fixed(k)));
  PairState state;
  state.position = x;
  state.node = nodes;
  std::vector<Point> f(x.size(), Point::Zero());
  const auto report = floor.add_forces(surface, state, f);
  EXPECT_EQ(report.contacts, 3);  // three bottom nodes, not four bottom pairs
  Eigen::VectorXd nodal = Eigen::VectorXd::Zero(dofs.num_dofs());
  add_pair_forces(mesh, dofs, f, nodal);
  for (int v : {0, 1, 2}) {
    const int n = dofs.vertex_nodes(v)[0];
    EXPECT_NEAR(nodal[2 * n + 1], k * 0.1, 1e-12) << "vertex " << v;
  }
  // Without the node map every pair is its own node: the middle vertex counts twice.
  state.node = {};
  std::fill(f.begin(), f.end(), Point::Zero());
  EXPECT_EQ(floor.add_forces(surface, state, f).contacts, 4);
}

TEST(RigidPlane, RefusesADegeneratePlane) {
  const PenaltyContact law(fixed(1.0));
  EXPECT_THROW(RigidPlane(Point(0, 0), Point(0, 0), law), InputError);
  EXPECT_THROW(RigidPlane(Point(0, std::nan("")), Point(0, 1), law), InputError);
  RigidPlane floor(Point(0, 1), Point(0, 1), law);
  EXPECT_NEAR(floor.gap(Point(3, 0.5)), -0.5, 1e-15);
}

}  // namespace
}  // namespace vorodg
