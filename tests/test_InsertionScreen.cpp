// The insertion check's screen (CrackInsertion::failing_edges; MohrCoulomb::worst_plane_factor):
//   - the worst plane's factor of a plane stress is the largest, over every plane through the
//     point, of max(sigma_n / sigma_o, (|tau| + mu sigma_n) / c): checked against 20,000 planes
//     for 200 random stresses of both signs (never above it, within 1e-6 of it);
//   - it decides failure: scaled by a strength factor 1e-4 above it, no plane fails; 1e-4 below,
//     some plane does;
//   - a mean of two stresses below a factor is below it on every plane (convexity, which the
//     screen rests on): 2000 random pairs, 50 planes each;
//   - on an rcp patch under random displacements of 41 rising amplitudes, with and without a
//     material variation, the screened check returns exactly the edges (and tractions) that
//     evaluating every edge returns: none, some, and most of them failing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/random/MaterialVariation.hpp"
#include "core/util/Random.hpp"
#include "dynamics/CrackInsertion.hpp"
#include "fracture/FaceInsertion.hpp"
#include "fracture/MohrCoulomb.hpp"
#include "support/DynamicsModel.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;

// The report's column: c = sigma_o = 3.7 MPa, mu = 0.75.
const MohrCoulomb kCriterion({3.7e6, 0.75, 3.7e6});

/// The factor at which the plane of normal angle theta through stress s reaches the criterion.
double plane_factor(const Eigen::Vector3d& s, double theta) {
  const Eigen::Vector2d n(std::cos(theta), std::sin(theta)), t(-n.y(), n.x());
  const Eigen::Vector2d tr = face_traction(s, n, t);
  const MohrCoulombParameters& p = kCriterion.parameters();
  return std::max(tr[0] / p.tensile_cutoff, (std::abs(tr[1]) + p.friction * tr[0]) / p.cohesion);
}

Eigen::Vector3d random_stress(Random& random) {
  return {random.uniform(-8e6, 5e6), random.uniform(-8e6, 5e6), random.uniform(-4e6, 4e6)};
}

TEST(InsertionScreen, WorstPlaneFactorIsTheWorstOfAllPlanes) {
  Random random(11);
  for (int i = 0; i < 200; ++i) {
    const Eigen::Vector3d s = random_stress(random);
    const double worst = kCriterion.worst_plane_factor(s[0], s[1], s[2]);
    double sampled = -1e300;
    for (int k = 0; k < 20000; ++k)
      sampled = std::max(sampled, plane_factor(s, std::numbers::pi * k / 20000.0));
    const double scale = std::max(std::abs(worst), 1e-3);
    EXPECT_LE(sampled, worst + 1e-12 * scale) << "stress " << s.transpose();
    EXPECT_GE(sampled, worst - 1e-6 * scale) << "stress " << s.transpose();
    if (worst <= 0.01) continue;  // a compressed point: no positive factor makes it fail
    bool fails_above = false, fails_below = false;
    for (int k = 0; k < 20000; ++k) {
      const double theta = std::numbers::pi * k / 20000.0;
      const Eigen::Vector2d n(std::cos(theta), std::sin(theta)), t(-n.y(), n.x());
      const Eigen::Vector2d tr = face_traction(s, n, t);
      fails_above = fails_above || face_utilization(kCriterion, tr, worst * (1 + 1e-4)) >= 1.0;
      fails_below = fails_below || face_utilization(kCriterion, tr, worst * (1 - 1e-4)) >= 1.0;
    }
    EXPECT_FALSE(fails_above) << "stress " << s.transpose();
    EXPECT_TRUE(fails_below) << "stress " << s.transpose();
  }
}

TEST(InsertionScreen, MeanOfStressesBelowAFactorStaysBelowIt) {
  Random random(12);
  int checked = 0;
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d a = random_stress(random), b = random_stress(random);
    const double f = std::max(kCriterion.worst_plane_factor(a[0], a[1], a[2]),
                              kCriterion.worst_plane_factor(b[0], b[1], b[2]));
    if (f <= 0.0) continue;
    const Eigen::Vector3d mean = 0.5 * (a + b);
    for (int k = 0; k < 50; ++k) {
      const double theta = random.uniform(0.0, std::numbers::pi);
      EXPECT_LE(plane_factor(mean, theta), f * (1 + 1e-12));
      ++checked;
    }
  }
  EXPECT_GT(checked, 50000);
}

/// The check without the screen: every eligible intact interior edge evaluated.
std::vector<CrackInsertion::Failure> every_edge_evaluated(const CrackInsertion& insertion,
                                                          const DynamicsModel& m,
                                                          const Eigen::VectorXd& u,
                                                          const std::vector<double>& strength) {
  const SplitDofMap dofs = SplitDofMap::continuous(m.mesh);
  const Eigen::Matrix3Xd sigma = insertion.cell_stresses(dofs, u, 1);
  std::vector<CrackInsertion::Failure> out;
  for (int e = 0; e < m.mesh.num_edges(); ++e) {
    if (m.mesh.edge(e).cell1 < 0) continue;
    const Eigen::Vector2d t = insertion.traction(sigma, e);
    if (face_utilization(kCriterion, t, strength.empty() ? 1.0 : strength[e]) >= 1.0)
      out.push_back({e, t});
  }
  return out;
}

TEST(InsertionScreen, ScreenedCheckFindsExactlyTheFailingEdges) {
  const DynamicsModel m(mesh_spec(MeshFamily::rcp, Rectangle(0, 0, 0.3, 0.3), 0.02),
                        IsotropicElasticity(28.3e9, 0.2, PlaneModel::strain), 2250.0);
  const std::vector<char> every(m.mesh.num_edges(), 1), none(m.mesh.num_edges(), 0);
  const SplitDofMap dofs = SplitDofMap::continuous(m.mesh);
  for (double variation : {0.0, 0.2}) {
    CrackInsertion insertion(m.mesh, m.integrator, kCriterion, every);
    const MaterialVariation v = MaterialVariation::uniform(m.mesh.num_cells(), variation, 4);
    insertion.vary(v);
    const std::vector<double> strength =
        v.empty() ? std::vector<double>{} : v.edge_strength(m.mesh);
    int interior = 0;
    for (const MeshEdge& e : m.mesh.edges()) interior += e.cell1 >= 0;
    bool saw_none = false, saw_some = false, saw_most = false;
    for (int k = 0; k <= 40; ++k) {  // 1e-7 to 1e-4, finely: many edges near their threshold
      const double amplitude = 1e-7 * std::pow(10.0, k / 13.3);
      const Eigen::VectorXd u = random_vector(dofs.num_dofs(), amplitude, 21);
      const auto screened = insertion.failing_edges(dofs, u, none, 1);
      const auto expected = every_edge_evaluated(insertion, m, u, strength);
      ASSERT_EQ(screened.size(), expected.size()) << "amplitude " << amplitude;
      for (std::size_t i = 0; i < expected.size(); ++i) {
        EXPECT_EQ(screened[i].edge, expected[i].edge);
        EXPECT_EQ(screened[i].traction, expected[i].traction);
      }
      const std::size_t n = expected.size();
      saw_none = saw_none || n == 0;
      saw_some = saw_some || (n > 0 && 4 * n < std::size_t(interior));
      saw_most = saw_most || 2 * n > std::size_t(interior);
    }
    EXPECT_TRUE(saw_none && saw_some && saw_most) << "the amplitudes span the cases";
  }
}

// The screen's edge case: a uniform uniaxial tension s n n^T along the normal n of an edge, just
// (1e-6) past the cutoff. That edge's plane is its cells' worst plane, so its cells are only
// 1e-6 past their factor and it fails: a screen that skipped edges a little too eagerly would
// miss it.
TEST(InsertionScreen, EdgesJustPastTheCriterionAreFound) {
  const DynamicsModel m(mesh_spec(MeshFamily::rcp, Rectangle(0, 0, 0.3, 0.3), 0.02),
                        IsotropicElasticity(28.3e9, 0.2, PlaneModel::strain), 2250.0);
  const std::vector<char> every(m.mesh.num_edges(), 1), none(m.mesh.num_edges(), 0);
  const SplitDofMap dofs = SplitDofMap::continuous(m.mesh);
  const CrackInsertion insertion(m.mesh, m.integrator, kCriterion, every);
  ASSERT_EQ(dofs.num_nodes(), m.mesh.num_vertices());  // the continuous map: node i is vertex i
  // The displacement u = E x of a uniform strain E, and the stress map from (exx, eyy, 2 exy).
  auto uniform = [&](const Eigen::Vector3d& e) {
    Eigen::VectorXd u(dofs.num_dofs());
    const Eigen::Matrix2d E{{e[0], 0.5 * e[2]}, {0.5 * e[2], e[1]}};
    for (int i = 0; i < dofs.num_nodes(); ++i) u.segment<2>(2 * i) = E * m.mesh.vertex(i);
    return u;
  };
  Eigen::Matrix3d stress_of_strain;
  for (int k = 0; k < 3; ++k)
    stress_of_strain.col(k) =
        insertion.cell_stresses(dofs, uniform(Eigen::Vector3d::Unit(k)), 1).col(0);
  int found = 0;
  for (int e = 0; e < m.mesh.num_edges(); e += 97) {
    if (m.mesh.edge(e).cell1 < 0) continue;
    const Point t = (m.mesh.vertex(m.mesh.edge(e).v1) - m.mesh.vertex(m.mesh.edge(e).v0));
    const Eigen::Vector2d n = Eigen::Vector2d(t.y(), -t.x()).normalized();
    const double s = kCriterion.parameters().tensile_cutoff * (1.0 + 1e-6);
    const Eigen::Vector3d sigma(s * n.x() * n.x(), s * n.y() * n.y(), s * n.x() * n.y());
    const Eigen::VectorXd u = uniform(stress_of_strain.lu().solve(sigma));
    const auto screened = insertion.failing_edges(dofs, u, none, 1);
    const auto expected = every_edge_evaluated(insertion, m, u, {});
    ASSERT_EQ(screened.size(), expected.size()) << "edge " << e;
    for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(screened[i].edge, expected[i].edge);
    found += std::any_of(expected.begin(), expected.end(),
                         [e](const CrackInsertion::Failure& f) { return f.edge == e; });
  }
  EXPECT_GT(found, 3);
}

}  // namespace
}  // namespace vorodg
