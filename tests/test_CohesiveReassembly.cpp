// CohesiveForces::reassemble: after a split the faces' openings are unchanged, so their forces
// are gathered onto the new nodes rather than evaluated again. On an rcp strip with a third of
// its interior edges cracked and opened at random, then split further: reassemble onto the new
// map gives, bit for bit, what evaluate gives at the copied displacements, and books no work.
#include <gtest/gtest.h>

#include "core/util/Random.hpp"
#include "dynamics/CohesiveForces.hpp"
#include "support/DynamicsModel.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;

constexpr double kE = 30e9, kH = 0.01;

/// Node displacements of `to` that copy those of `from`, pair by pair (a split's remap).
Eigen::VectorXd copied(const PolygonMesh& mesh, const SplitDofMap& from, const SplitDofMap& to,
                       const Eigen::VectorXd& u) {
  Eigen::VectorXd out = Eigen::VectorXd::Zero(to.num_dofs());
  for (int c = 0; c < mesh.num_cells(); ++c)
    for (int k = 0; k < mesh.cell_size(c); ++k)
      out.segment<2>(2 * to.node(c, k)) = u.segment<2>(2 * from.node(c, k));
  return out;
}

TEST(CohesiveReassembly, GathersWhatEvaluateWouldGiveAfterASplit) {
  const DynamicsModel m(mesh_spec(MeshFamily::rcp, Rectangle(0, 0, 20 * kH, 5 * kH), kH),
                        IsotropicElasticity(kE, 0.2, PlaneModel::strain), 2400.0);
  const CohesiveLaw law(CohesiveParameters{3e6, 50.0, 1.0, "linear", 10 * kE / kH});
  CohesiveForces faces(m.mesh, law);
  Random random(21);
  std::vector<char> connected(m.mesh.num_edges(), 1), more(m.mesh.num_edges(), 1);
  for (int e = 0; e < m.mesh.num_edges(); ++e) {
    if (m.mesh.edge(e).on_boundary()) continue;
    const double draw = random.uniform();
    if (draw < 0.33) {
      faces.add_edge(e);
      connected[e] = more[e] = 0;
    } else if (draw < 0.5) {
      more[e] = 0;  // cracks later, with the split
    }
  }
  const SplitDofMap before(m.mesh, connected), after(m.mesh, more);
  ASSERT_GT(after.num_nodes(), before.num_nodes());
  faces.bind(before);
  // Openings of up to a few critical openings, so that points sit on every branch of the law.
  const Eigen::VectorXd u = random_vector(before.num_dofs(), 3.0 * law.critical_opening(), 22);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(before.num_dofs());
  faces.evaluate(u, f);
  const double work = faces.work();
  // The split: the same faces on the finer map, at copied displacements.
  faces.bind(after);
  Eigen::VectorXd gathered = Eigen::VectorXd::Zero(after.num_dofs());
  faces.reassemble(gathered);
  EXPECT_EQ(faces.work(), work);
  Eigen::VectorXd evaluated = Eigen::VectorXd::Zero(after.num_dofs());
  faces.evaluate(copied(m.mesh, before, after, u), evaluated);
  EXPECT_GT(evaluated.norm(), 0.0);
  EXPECT_EQ((gathered - evaluated).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(faces.work(), work);  // the openings did not move
}

}  // namespace
}  // namespace vorodg
