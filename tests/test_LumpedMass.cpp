// Row-sum lumped masses (dynamics/LumpedMass) on every generated mesh family:
//   - every (cell, vertex) pair mass is positive, and the total is rho times the domain area to
//     1e-12 relative (the per-family smallest and largest pair mass relative to rho |c| / n are
//     printed);
//   - a pair mass is the row sum of the consistent mass matrix rho sum_q w_q psi_k psi_l (the
//     shape functions sum to one), to 1e-12 relative;
//   - node masses of the continuous and fully discontinuous maps are the sums of their pairs,
//     and copying node velocities to the split nodes keeps the momentum;
//   - a non-positive density is refused, and so is an element table built without psi.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "core/dofs/SplitDofMap.hpp"
#include "core/util/Errors.hpp"
#include "dynamics/LumpedMass.hpp"
#include "support/ElementTestMeshes.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;

constexpr double kDensity = 7800.0;

TEST(LumpedMass, PositiveAndTotalIsDensityTimesArea) {
  for (const Family& f : kFamilies) {
    const ElementTable& table = table_of(f, 3, true);
    const PolygonMesh& mesh = table.mesh();
    const LumpedMass mass(table, kDensity);
    double lo = 1e300, hi = 0.0;
    for (int c = 0; c < mesh.num_cells(); ++c) {
      const double share = kDensity * mesh.cell_area(c) / mesh.cell_size(c);
      for (int k = 0; k < mesh.cell_size(c); ++k) {
        ASSERT_GT(mass.pair_mass(c, k), 0.0) << f.name << " cell " << c << " vertex " << k;
        lo = std::min(lo, mass.pair_mass(c, k) / share);
        hi = std::max(hi, mass.pair_mass(c, k) / share);
      }
    }
    const double exact = kDensity * mesh.domain().area();
    const double error = std::abs(mass.total() - exact) / exact;
    std::printf(
        "%-18s %5d cells: total mass error %.2e, pair mass / (rho |c| / n) in [%.3f, %.3f]\n",
        f.name, mesh.num_cells(), error, lo, hi);
    EXPECT_LT(error, 1e-12) << f.name;
  }
}

TEST(LumpedMass, IsTheRowSumOfTheConsistentMass) {
  for (const Family& f : kFamilies) {
    const ElementTable& table = table_of(f, 3, true);
    const LumpedMass mass(table, kDensity);
    for (int c = 0; c < table.mesh().num_cells(); c += 7) {
      const int n = table.num_nodes(c);
      for (int k = 0; k < n; ++k) {
        double row = 0.0;
        for (int q = 0; q < table.num_points(c); ++q)
          for (int l = 0; l < n; ++l)
            row += kDensity * table.weight(c, q) * table.shape(c, q, k) * table.shape(c, q, l);
        EXPECT_NEAR(row, mass.pair_mass(c, k), 1e-12 * mass.pair_mass(c, k))
            << f.name << " cell " << c << " vertex " << k;
      }
    }
  }
}

TEST(LumpedMass, NodeMassesAreSumsOfPairsAndSplitsKeepMomentum) {
  const ElementTable& table = table_of(kFamilies[0], 3, true);
  const PolygonMesh& mesh = table.mesh();
  const LumpedMass mass(table, kDensity);
  const SplitDofMap joined = SplitDofMap::continuous(mesh);
  const SplitDofMap split = SplitDofMap::discontinuous(mesh);
  const Eigen::VectorXd mj = mass.node_masses(joined), ms = mass.node_masses(split);
  ASSERT_EQ(mj.size(), mesh.num_vertices());
  ASSERT_EQ(ms.size(), mass.num_pairs());
  EXPECT_NEAR(mj.sum(), mass.total(), 1e-12 * mass.total());
  for (int c = 0; c < mesh.num_cells(); ++c)
    for (int k = 0; k < mesh.cell_size(c); ++k)
      EXPECT_EQ(ms[split.node(c, k)], mass.pair_mass(c, k));
  // Velocities of the joined nodes copied to the split ones: the momentum does not change.
  Eigen::Vector2d pj = Eigen::Vector2d::Zero(), ps = Eigen::Vector2d::Zero();
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const Eigen::Vector2d vel(std::sin(3.0 * v), std::cos(5.0 * v));
    pj += mj[joined.vertex_nodes(v)[0]] * vel;
    for (int node : split.vertex_nodes(v)) ps += ms[node] * vel;
  }
  EXPECT_LT((pj - ps).norm(), 1e-12 * pj.norm());
}

TEST(LumpedMass, RefusesANonPositiveDensity) {
  const ElementTable& table = table_of(kFamilies[0], 3, true);
  EXPECT_THROW(LumpedMass(table, 0.0), InputError);
  EXPECT_THROW(LumpedMass(table, -1.0), InputError);
}

TEST(LumpedMass, RefusesATableWithoutShapeValues) {
  ElementOptions o;
  o.shape_values = false;
  const ElementTable table(mesh_of(kFamilies[0]), o);
  EXPECT_THROW(LumpedMass(table, kDensity), NumericalError);
}

}  // namespace
}  // namespace vorodg
