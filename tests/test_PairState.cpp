// The per-pair view of nodal fields that contact reads and writes: positions X + u, velocities
// and masses read through a split DOF map, forces summed back onto the nodes, sizes checked.
#include "dynamics/contact/PairState.hpp"

#include <gtest/gtest.h>

#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Random.hpp"

namespace vorodg {
namespace {

PolygonMesh small_rcp() {
  MeshSpec spec;
  spec.domain = Rectangle(0.0, 0.0, 1.0, 0.5);
  spec.size = 0.1;
  spec.seed = 3;
  return generate_mesh(spec).mesh;
}

TEST(PairState, PositionsAreReferencePlusNodalDisplacement) {
  const PolygonMesh mesh = small_rcp();
  for (const SplitDofMap& dofs :
       {SplitDofMap::continuous(mesh), SplitDofMap::discontinuous(mesh)}) {
    Random random(4);
    Eigen::VectorXd u(dofs.num_dofs());
    for (Eigen::Index i = 0; i < u.size(); ++i) u[i] = random.uniform(-1.0, 1.0);
    const auto x = pair_positions(mesh, dofs, u);
    const auto nodes = pair_nodes(mesh, dofs);
    ASSERT_EQ(int(x.size()), mesh.offsets().back());
    for (int c = 0; c < mesh.num_cells(); ++c)
      for (int k = 0; k < mesh.cell_size(c); ++k) {
        const int p = mesh.offsets()[c] + k, n = dofs.node(c, k);
        EXPECT_EQ(nodes[p], n);
        EXPECT_EQ(x[p], mesh.vertex(mesh.cell_vertices(c)[k]) + Point(u[2 * n], u[2 * n + 1]));
      }
  }
}

TEST(PairState, ForcesGatherOntoNodesAndScalarsSpread) {
  const PolygonMesh mesh = small_rcp();
  const SplitDofMap dofs = SplitDofMap::continuous(mesh);
  // A unit force on every pair: a node gets as many as it has pairs (its vertex's cells).
  const std::vector<Point> force(mesh.offsets().back(), Point(1.0, -2.0));
  Eigen::VectorXd f = Eigen::VectorXd::Zero(dofs.num_dofs());
  add_pair_forces(mesh, dofs, force, f);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const int n = dofs.vertex_nodes(v)[0];
    EXPECT_EQ(f[2 * n], double(mesh.vertex_cells(v).size()));
    EXPECT_EQ(f[2 * n + 1], -2.0 * double(mesh.vertex_cells(v).size()));
  }
  const Eigen::VectorXd mass = Eigen::VectorXd::LinSpaced(dofs.num_nodes(), 1.0, 2.0);
  const auto m = pair_scalars(mesh, dofs, mass);
  for (int c = 0; c < mesh.num_cells(); ++c)
    for (int k = 0; k < mesh.cell_size(c); ++k)
      EXPECT_EQ(m[mesh.offsets()[c] + k], mass[dofs.node(c, k)]);
}

TEST(PairState, WrongSizesAreRefused) {
  const PolygonMesh mesh = small_rcp();
  const SplitDofMap dofs = SplitDofMap::continuous(mesh);
  EXPECT_THROW(pair_positions(mesh, dofs, Eigen::VectorXd::Zero(3)), InputError);
  EXPECT_THROW(pair_scalars(mesh, dofs, Eigen::VectorXd::Zero(3)), InputError);
  std::vector<Point> x(mesh.offsets().back(), Point::Zero());
  std::vector<double> short_mass(5, 1.0);
  PairState state;
  state.position = x;
  EXPECT_NO_THROW(check_pair_state(mesh, state, "test"));
  state.mass = short_mass;
  EXPECT_THROW(check_pair_state(mesh, state, "test"), InputError);
  state.mass = {};
  state.position = std::span<const Point>(x).first(3);
  EXPECT_THROW(check_pair_state(mesh, state, "test"), InputError);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(dofs.num_dofs() + 2);
  EXPECT_THROW(add_pair_forces(mesh, dofs, x, f), InputError);
}

}  // namespace
}  // namespace vorodg
