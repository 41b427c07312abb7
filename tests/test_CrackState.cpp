// CrackState (fracture/CrackState) on an rcp mesh of [0,2] x [0,1] (d = 0.1, seed 17):
//   - the Hamming distance is a metric on random states (seed 5): symmetric, zero iff the
//     states are equal, triangle inequality over every triple;
//   - the opening distance is zero iff the openings are equal, symmetric, obeys the triangle
//     inequality, and equals |dw| L_e / (total interior length) for one edge, to 1e-15 relative;
//   - from a SplitDofMap: the continuous map has no crack, the discontinuous one every interior
//     edge, a map cut along a line has exactly that line cracked, and one unconnected edge
//     inside the body (no node splits) is no crack;
//   - states of different meshes, wrong sizes and bad openings are refused with InputError.
#include <gtest/gtest.h>

#include <vector>

#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Random.hpp"
#include "fracture/CrackState.hpp"

namespace vorodg {
namespace {

PolygonMesh rcp_mesh() {
  MeshSpec spec;
  spec.family = MeshFamily::rcp;
  spec.domain = Rectangle(0.0, 0.0, 2.0, 1.0);
  spec.size = 0.1;
  spec.seed = 17;
  return generate_mesh(spec).mesh;
}

const PolygonMesh& mesh() {
  static const PolygonMesh m = rcp_mesh();
  return m;
}

std::vector<char> random_flags(Random& random, double p) {
  std::vector<char> flags(mesh().num_edges());
  for (char& f : flags) f = random.uniform() < p ? 1 : 0;
  return flags;
}

/// A state with random openings in (0, 1] on its cracked edges.
CrackState random_opened(Random& random, double p) {
  const std::vector<char> flags = random_flags(random, p);
  Eigen::VectorXd w = Eigen::VectorXd::Zero(mesh().num_edges());
  for (int e = 0; e < mesh().num_edges(); ++e)
    if (flags[e] && !mesh().edge(e).on_boundary()) w[e] = 1.0 - random.uniform();
  return CrackState(mesh(), flags, w);
}

/// Interior edges whose cells' centroids lie on either side of x = 1: a cut through the body.
std::vector<char> cut_at_one() {
  std::vector<char> cut(mesh().num_edges(), 0);
  for (int e = 0; e < mesh().num_edges(); ++e) {
    const MeshEdge& edge = mesh().edge(e);
    if (edge.on_boundary()) continue;
    cut[e] = (mesh().cell_centroid(edge.cell0).x() < 1.0) !=
             (mesh().cell_centroid(edge.cell1).x() < 1.0);
  }
  return cut;
}

TEST(CrackState, BoundaryFlagsAreDroppedAndCounted) {
  const CrackState all(mesh(), std::vector<char>(mesh().num_edges(), 1));
  int interior = 0;
  for (const MeshEdge& edge : mesh().edges()) interior += !edge.on_boundary();
  EXPECT_EQ(all.num_cracked(), interior);
  for (int e = 0; e < mesh().num_edges(); ++e)
    EXPECT_EQ(all.cracked(e), !mesh().edge(e).on_boundary());
  EXPECT_EQ(CrackState(mesh(), std::vector<char>(mesh().num_edges(), 0)).num_cracked(), 0);
}

TEST(CrackState, HammingIsAMetric) {
  Random random(5);
  std::vector<CrackState> states;
  for (int i = 0; i < 12; ++i) states.emplace_back(mesh(), random_flags(random, 0.1 + 0.05 * i));
  states.push_back(states[3]);  // an equal copy
  const int n = static_cast<int>(states.size());
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const int d = CrackState::hamming(states[i], states[j]);
      EXPECT_EQ(d, CrackState::hamming(states[j], states[i]));
      EXPECT_EQ(d == 0, states[i].flags() == states[j].flags()) << i << " " << j;
      for (int k = 0; k < n; ++k)
        EXPECT_LE(d, CrackState::hamming(states[i], states[k]) +
                         CrackState::hamming(states[k], states[j]));
    }
  EXPECT_EQ(CrackState::hamming(states[3], states.back()), 0);
  const CrackState none(mesh(), std::vector<char>(mesh().num_edges(), 0));
  EXPECT_EQ(CrackState::hamming(none, states[0]), states[0].num_cracked());
}

TEST(CrackState, OpeningDistanceIsZeroIffOpeningsAreEqual) {
  Random random(5);
  std::vector<CrackState> states;
  for (int i = 0; i < 8; ++i) states.push_back(random_opened(random, 0.3));
  states.push_back(states[2]);
  const int n = static_cast<int>(states.size());
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double d = CrackState::opening_distance(states[i], states[j]);
      EXPECT_EQ(d, CrackState::opening_distance(states[j], states[i]));
      EXPECT_EQ(d == 0.0, states[i].openings() == states[j].openings()) << i << " " << j;
      for (int k = 0; k < n; ++k)
        EXPECT_LE(d, (1 + 1e-14) * (CrackState::opening_distance(states[i], states[k]) +
                                    CrackState::opening_distance(states[k], states[j])));
    }
}

TEST(CrackState, OpeningDistanceOfOneEdgeIsItsWeightedOpening) {
  double total = 0.0;
  int e0 = -1;
  for (int e = 0; e < mesh().num_edges(); ++e)
    if (!mesh().edge(e).on_boundary()) total += mesh().edge_length(e), e0 = e0 < 0 ? e : e0;
  std::vector<char> flags(mesh().num_edges(), 0);
  flags[e0] = 1;
  Eigen::VectorXd w = Eigen::VectorXd::Zero(mesh().num_edges());
  const CrackState closed(mesh(), flags, w);
  w[e0] = 2.5e-3;
  const CrackState open(mesh(), flags, w);
  const double expected = 2.5e-3 * mesh().edge_length(e0) / total;
  EXPECT_NEAR(CrackState::opening_distance(closed, open), expected, 1e-15 * expected);
  // A cracked edge with zero opening and an uncracked edge are the same to d_cfod, not to
  // the Hamming distance.
  const CrackState uncracked(mesh(), std::vector<char>(mesh().num_edges(), 0),
                             Eigen::VectorXd::Zero(mesh().num_edges()));
  EXPECT_EQ(CrackState::opening_distance(closed, uncracked), 0.0);
  EXPECT_EQ(CrackState::hamming(closed, uncracked), 1);
}

TEST(CrackState, FromSplitDofMap) {
  EXPECT_EQ(CrackState::from_dofs(mesh(), SplitDofMap::continuous(mesh())).num_cracked(), 0);
  const CrackState all = CrackState::from_dofs(mesh(), SplitDofMap::discontinuous(mesh()));
  EXPECT_EQ(CrackState::hamming(all, CrackState(mesh(), std::vector<char>(mesh().num_edges(), 1))),
            0);
  const std::vector<char> cut = cut_at_one();
  std::vector<char> connected(cut.size());
  for (std::size_t e = 0; e < cut.size(); ++e) connected[e] = !cut[e];
  const CrackState from_map = CrackState::from_dofs(mesh(), SplitDofMap(mesh(), connected));
  EXPECT_GT(from_map.num_cracked(), 5);
  EXPECT_EQ(CrackState::hamming(from_map, CrackState(mesh(), cut)), 0);
  // One unconnected edge between two interior vertices splits no node: no crack in the map.
  const double tol = 1e-8 * mesh().domain().scale();
  const auto inside = [&](int v) {
    const auto near = mesh().domain().sides_near(mesh().vertex(v), tol);
    return !(near[0] || near[1] || near[2] || near[3]);
  };
  int e0 = 0;
  while (!inside(mesh().edge(e0).v0) || !inside(mesh().edge(e0).v1)) ++e0;
  std::vector<char> all_but_one(mesh().num_edges(), 1);
  all_but_one[e0] = 0;
  EXPECT_EQ(CrackState::from_dofs(mesh(), SplitDofMap(mesh(), all_but_one)).num_cracked(), 0);
}

TEST(CrackState, RefusesBadInput) {
  const PolygonMesh twin = rcp_mesh();  // equal, but another mesh object
  const CrackState a(mesh(), std::vector<char>(mesh().num_edges(), 0));
  const CrackState b(twin, std::vector<char>(twin.num_edges(), 0));
  EXPECT_THROW(CrackState::hamming(a, b), InputError);
  EXPECT_THROW(CrackState(mesh(), std::vector<char>(3, 0)), InputError);
  EXPECT_THROW(CrackState::opening_distance(a, a), InputError);  // no openings
  std::vector<char> flags(mesh().num_edges(), 0);
  Eigen::VectorXd w = Eigen::VectorXd::Zero(mesh().num_edges());
  w[0] = 1e-3;  // on an uncracked edge
  EXPECT_THROW(CrackState(mesh(), flags, w), InputError);
  int interior = 0;
  while (mesh().edge(interior).on_boundary()) ++interior;
  flags[interior] = 1;
  w.setZero();
  w[interior] = -1e-3;
  EXPECT_THROW(CrackState(mesh(), flags, w), InputError);
  EXPECT_THROW(CrackState(mesh(), flags, Eigen::VectorXd::Zero(2)), InputError);
}

}  // namespace
}  // namespace vorodg
