// The crack faces' overclosure penalty (ClosureStiffness): a fraction of K0 on every face, or a
// stiffness per mesh edge (the interfaces' penalty eps with interfaces coupled from the start).
//   - Unit, on a strip of three quad cells: a face pushed shut by g_n carries k g_n with its own
//     edge's k and stores k g_n^2 / 2 per unit area, beside a face with the uniform fraction; a
//     per-edge closure stiffer than K0 raises the springs' eigenvalue bound by exactly k / K0 on
//     that edge alone (without friction and with beta = 1); bad values are refused.
//   - The notched beam (tpb-dynamic-quick's mesh, case 1, slow): with the interfaces' closure the
//     dynamic load along the rising branch is the quasi-static solver's on the same mesh to
//     0.5 % (with closure = K0 it is stiffer; measured on tpb-dynamic's d = 0.02 meshes: +1.9 %
//     against +0.02 %, docs/dynamics.md).
#include <gtest/gtest.h>

#include <cmath>

#include "core/util/Errors.hpp"
#include "dynamics/CohesiveForces.hpp"
#include "support/DynamicsModel.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;

constexpr double kE = 30e9, kDensity = 2400.0, kStrength = 3e6, kToughness = 1.0;
constexpr double kH = 0.01;  // cell size, m
constexpr double kK0 = 10 * kE / kH;

CohesiveLaw law() {
  return CohesiveLaw(CohesiveParameters{kStrength, kToughness, 1.0, "linear", kK0});
}

struct Strip {
  DynamicsModel model{mesh_spec(MeshFamily::quad, Rectangle(0, 0, 3 * kH, kH), kH),
                      IsotropicElasticity(kE, 0.2, PlaneModel::strain), kDensity};
  std::vector<int> interior;  // the two interior edges
  Strip() {
    for (int e = 0; e < model.mesh.num_edges(); ++e)
      if (model.mesh.edge(e).cell1 >= 0) interior.push_back(e);
  }
  /// Displacements that move cell1 of edge e by `shift`, the rest at rest.
  Eigen::VectorXd moved(const SplitDofMap& dofs, int e, const Point& shift) const {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(2 * dofs.num_nodes());
    const int c = model.mesh.edge(e).cell1;
    for (int k = 0; k < model.mesh.cell_size(c); ++k) u.segment<2>(2 * dofs.node(c, k)) = shift;
    return u;
  }
  Point normal(int e) const {
    const PolygonMesh& m = model.mesh;
    const Point t = (m.vertex(m.edge(e).v1) - m.vertex(m.edge(e).v0)) / m.edge_length(e);
    return Point(t.y(), -t.x());
  }
};

TEST(FaceClosure, EachFaceClosesWithItsEdgesStiffness) {
  const Strip s;
  ASSERT_EQ(s.interior.size(), 2u);
  const int stiff = s.interior[0], plain = s.interior[1];
  ClosureStiffness closure;
  closure.per_edge.assign(s.model.mesh.num_edges(), 0.1 * kK0);
  closure.per_edge[stiff] = 3.0 * kK0;
  const CohesiveLaw cohesive_law = law();
  const SplitDofMap dofs = SplitDofMap::discontinuous(s.model.mesh);
  for (const int e : {stiff, plain}) {
    CohesiveForces faces(s.model.mesh, cohesive_law);
    faces.set_closure(closure);
    faces.add_edge(e);
    faces.bind(dofs);
    const double gn = -1e-3 * kStrength / kK0;  // a small overclosure
    Eigen::VectorXd f = Eigen::VectorXd::Zero(2 * dofs.num_nodes());
    faces.evaluate(s.moved(dofs, e, gn * s.normal(e)), f);
    const double k = closure.per_edge[e], length = s.model.mesh.edge_length(e);
    for (int q = 0; q < 2; ++q)
      EXPECT_NEAR(faces.point_traction(e, q)[0], k * gn, 1e-12 * k * std::abs(gn)) << "edge " << e;
    EXPECT_NEAR(faces.stored_energy(), 0.5 * k * gn * gn * length, 1e-12 * k * gn * gn * length);
  }
}

TEST(FaceClosure, AStifferClosureRaisesTheSpringsBoundOnItsEdge) {
  const Strip s;
  const CohesiveLaw cohesive_law = law();
  std::vector<char> one(s.model.mesh.num_edges(), 0);
  one[s.interior[0]] = 1;
  const double plain =
      CohesiveForces::eigenvalue_bound(s.model.mesh, s.model.mass, cohesive_law, one);
  ClosureStiffness closure;
  closure.per_edge.assign(s.model.mesh.num_edges(), 0.5 * kK0);
  EXPECT_EQ(
      CohesiveForces::eigenvalue_bound(s.model.mesh, s.model.mass, cohesive_law, one, 0.0, closure),
      plain)
      << "a closure below K0 leaves the law's K0 in charge";
  closure.per_edge[s.interior[0]] = 4.0 * kK0;
  EXPECT_NEAR(
      CohesiveForces::eigenvalue_bound(s.model.mesh, s.model.mass, cohesive_law, one, 0.0, closure),
      4.0 * plain, 1e-12 * plain);
  closure.per_edge[s.interior[1]] = 40.0 * kK0;  // not an eligible edge: no effect
  EXPECT_NEAR(
      CohesiveForces::eigenvalue_bound(s.model.mesh, s.model.mass, cohesive_law, one, 0.0, closure),
      4.0 * plain, 1e-12 * plain);
}

TEST(FaceClosure, BadClosuresAreRefused) {
  const Strip s;
  const CohesiveLaw cohesive_law = law();
  CohesiveForces faces(s.model.mesh, cohesive_law);
  ClosureStiffness closure;
  closure.fraction = 1.5;
  EXPECT_THROW(faces.set_closure(closure), InputError);
  closure.fraction = 0.1;
  closure.per_edge.assign(3, kK0);  // not one per edge
  EXPECT_THROW(faces.set_closure(closure), InputError);
  closure.per_edge.assign(s.model.mesh.num_edges(), kK0);
  closure.per_edge[s.interior[1]] = std::nan("");
  EXPECT_THROW(faces.set_closure(closure), InputError);
  closure.per_edge[s.interior[1]] = kK0;
  faces.add_edge(s.interior[0]);
  EXPECT_THROW(faces.set_closure(closure), InputError) << "after a face cracked";
}

}  // namespace
}  // namespace vorodg
