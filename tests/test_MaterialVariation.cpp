// Per-cell material variation (dynamics/MaterialVariation; docs/impact.md):
//   - the factors lie in [1 - x, 1 + x], depend only on the seed (the same seed gives the same
//     factors, another seed others), x = 0 gives the uniform material, x outside [0, 1) is an
//     InputError; an edge's strength factor is the mean of its cells' (its cell's on the boundary);
//   - CrackInsertion::vary on a strip (quads, nu = 0) under the uniform strain with E eps =
//     sigma_o: every cell's stress is its stiffness factor times E eps, and exactly the
//     cross-section edges whose cells' mean stiffness factor reaches their mean strength factor
//     fail (checked against that rule edge by edge);
//   - CohesiveForces::set_edge_strength: an edge opened uniformly to its scaled law's peak
//     opening f sigma_c / K0 carries f sigma_c (the force on one side is -L f sigma_c n, to 1e-12),
//     and an edge of another factor carries its own law's traction at the same opening.
#include <gtest/gtest.h>

#include "core/random/MaterialVariation.hpp"
#include "core/util/Errors.hpp"
#include "dynamics/CohesiveForces.hpp"
#include "dynamics/CrackInsertion.hpp"
#include "support/DynamicsModel.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;

constexpr double kE = 30e9, kCutoff = 3e6, kH = 0.01;

DynamicsModel strip() {
  return {mesh_spec(MeshFamily::quad, Rectangle(0, 0, 0.2, kH), kH),
          IsotropicElasticity(kE, 0.0, PlaneModel::stress), 2400.0};
}

TEST(MaterialVariation, FactorsAreUniformAndSeeded) {
  const MaterialVariation a = MaterialVariation::uniform(500, 0.05, 7);
  const MaterialVariation b = MaterialVariation::uniform(500, 0.05, 7);
  const MaterialVariation c = MaterialVariation::uniform(500, 0.05, 8);
  ASSERT_EQ(a.stiffness.size(), 500u);
  double lo = 2, hi = 0;
  for (int i = 0; i < 500; ++i) {
    for (double f : {a.stiffness[i], a.strength[i]}) lo = std::min(lo, f), hi = std::max(hi, f);
    EXPECT_EQ(a.stiffness[i], b.stiffness[i]);
    EXPECT_EQ(a.strength[i], b.strength[i]);
  }
  EXPECT_GE(lo, 0.95);
  EXPECT_LT(hi, 1.05);
  EXPECT_LT(lo, 0.951);  // 1000 draws reach near both ends
  EXPECT_GT(hi, 1.049);
  EXPECT_NE(a.stiffness, c.stiffness);
  EXPECT_TRUE(MaterialVariation::uniform(10, 0.0, 7).empty());
  EXPECT_THROW(MaterialVariation::uniform(10, 1.0, 7), InputError);
  EXPECT_THROW(MaterialVariation::uniform(10, -0.1, 7), InputError);
  const DynamicsModel m = strip();
  const MaterialVariation v = MaterialVariation::uniform(m.mesh.num_cells(), 0.1, 3);
  const std::vector<double> edge = v.edge_strength(m.mesh);
  for (int e = 0; e < m.mesh.num_edges(); ++e) {
    const MeshEdge& x = m.mesh.edge(e);
    const double expected =
        x.cell1 < 0 ? v.strength[x.cell0] : 0.5 * (v.strength[x.cell0] + v.strength[x.cell1]);
    EXPECT_DOUBLE_EQ(edge[e], expected);
  }
}

TEST(MaterialVariation, InsertionScalesStressAndStrength) {
  const DynamicsModel m = strip();
  const MaterialVariation v = MaterialVariation::uniform(m.mesh.num_cells(), 0.1, 11);
  CrackInsertion insertion(m.mesh, m.integrator, MohrCoulomb({100 * kCutoff, 0.0, kCutoff}),
                           std::vector<char>(m.mesh.num_edges(), 1));
  insertion.vary(v);
  const SplitDofMap dofs = SplitDofMap::continuous(m.mesh);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(2 * dofs.num_nodes());
  const double strain = kCutoff / kE;
  for (int c = 0; c < m.mesh.num_cells(); ++c)
    for (int k = 0; k < m.mesh.cell_size(c); ++k)
      u[2 * dofs.node(c, k)] = strain * m.mesh.vertex(m.mesh.cell_vertices(c)[k]).x();
  const Eigen::Matrix3Xd sigma = insertion.cell_stresses(dofs, u, 1);
  for (int c = 0; c < m.mesh.num_cells(); ++c)
    EXPECT_NEAR(sigma(0, c), v.stiffness[c] * kCutoff, 1e-9 * kCutoff);
  std::vector<int> expected;
  for (int e = 0; e < m.mesh.num_edges(); ++e) {
    const MeshEdge& x = m.mesh.edge(e);
    if (x.cell1 < 0) continue;
    const bool section = std::abs(m.mesh.vertex(x.v0).x() - m.mesh.vertex(x.v1).x()) < 1e-12;
    const double load = 0.5 * (v.stiffness[x.cell0] + v.stiffness[x.cell1]);
    const double strength = 0.5 * (v.strength[x.cell0] + v.strength[x.cell1]);
    if (section && load >= strength) expected.push_back(e);
  }
  std::vector<int> found;
  for (const auto& f :
       insertion.failing_edges(dofs, u, std::vector<char>(m.mesh.num_edges(), 0), 1))
    found.push_back(f.edge);
  EXPECT_FALSE(expected.empty());
  EXPECT_EQ(found, expected);
}

TEST(MaterialVariation, EachEdgeCarriesItsOwnStrength) {
  const DynamicsModel m = strip();
  const CohesiveLaw law(CohesiveParameters{kCutoff, 50.0, 1.0, "linear", 10 * kE / kH});
  CohesiveForces faces(m.mesh, law);
  std::vector<double> factor(m.mesh.num_edges(), 1.0);
  std::vector<int> interior;
  for (int e = 0; e < m.mesh.num_edges(); ++e)
    if (m.mesh.edge(e).cell1 >= 0) interior.push_back(e);
  const int a = interior[3], b = interior[10];
  factor[a] = 1.08, factor[b] = 0.93;
  faces.set_edge_strength(factor);
  faces.add_edge(a);
  faces.add_edge(b);
  EXPECT_THROW(faces.set_edge_strength(factor), InputError);
  const SplitDofMap dofs = SplitDofMap::discontinuous(m.mesh);
  faces.bind(dofs);
  // Open both edges by edge a's scaled peak opening: cell1's side moves along the normal.
  const double opening = factor[a] * kCutoff / law.parameters().initial_stiffness;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(2 * dofs.num_nodes());
  for (int e : {a, b}) {
    const MeshEdge& x = m.mesh.edge(e);
    const Point t = (m.mesh.vertex(x.v1) - m.mesh.vertex(x.v0)).normalized();
    const Point n(t.y(), -t.x());
    for (int k = 0; k < m.mesh.cell_size(x.cell1); ++k)
      u.segment<2>(2 * dofs.node(x.cell1, k)) = opening * n;
  }
  Eigen::VectorXd f = Eigen::VectorXd::Zero(u.size());
  faces.evaluate(u, f);
  for (int e : {a, b}) {
    const MeshEdge& x = m.mesh.edge(e);
    const Point d = m.mesh.vertex(x.v1) - m.mesh.vertex(x.v0);
    const Point n(d.normalized().y(), -d.normalized().x());
    CohesiveParameters p = law.parameters();
    p.strength *= factor[e];
    CohesiveLaw::State state;
    const double expected =
        CohesiveLaw(p).respond(Eigen::Vector2d(opening, 0.0), state).traction[0];
    double pull = 0.0;  // the force on cell1's side, along n
    for (int k = 0; k < m.mesh.cell_size(x.cell1); ++k)
      pull += f.segment<2>(2 * dofs.node(x.cell1, k)).dot(n);
    EXPECT_NEAR(pull, -d.norm() * expected, 1e-12 * d.norm() * kCutoff) << "edge " << e;
    if (e == a) {
      EXPECT_NEAR(expected, factor[a] * kCutoff, 1e-9 * kCutoff);
    } else {
      EXPECT_LT(expected, factor[b] * kCutoff);  // past b's peak: softening
    }
  }
}

}  // namespace
}  // namespace vorodg
