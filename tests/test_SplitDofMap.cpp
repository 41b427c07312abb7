// The split DOF map's two ends and a line between them: all edges connected is the continuous
// space (a node per vertex), none the discontinuous one (a node per cell corner), and a straight
// line of split edges doubles exactly the vertices strictly inside the domain on it, plus the two
// on its ends at the boundary; disconnecting edges batch by batch gives the map built from
// scratch.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <set>

#include "core/dofs/SplitDofMap.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Random.hpp"

namespace vorodg {
namespace {

GeneratedMesh mesh_of(MeshFamily family) {
  MeshSpec spec;
  spec.family = family;
  spec.domain = Rectangle(0.0, 0.0, 1.0, 0.5);
  spec.size = 0.1;
  spec.seed = 7;
  return generate_mesh(spec);
}

TEST(SplitDofMap, AllConnectedIsContinuousNoneIsDiscontinuous) {
  for (MeshFamily f : {MeshFamily::rcp, MeshFamily::quad, MeshFamily::perturbed_hex}) {
    const PolygonMesh& mesh = mesh_of(f).mesh;
    const SplitDofMap cg = SplitDofMap::continuous(mesh);
    EXPECT_EQ(cg.num_nodes(), mesh.num_vertices());
    for (int v = 0; v < mesh.num_vertices(); ++v) EXPECT_EQ(cg.vertex_nodes(v).size(), 1u);
    const SplitDofMap dg = SplitDofMap::discontinuous(mesh);
    EXPECT_EQ(dg.num_nodes(), mesh.offsets().back());
    for (int e = 0; e < mesh.num_edges(); ++e)
      if (!mesh.edge(e).on_boundary()) {
        EXPECT_TRUE(cg.joins(mesh, e));
        EXPECT_FALSE(dg.joins(mesh, e));
      }
  }
}

TEST(SplitDofMap, ALineOfSplitEdgesDoublesItsVertices) {
  const PolygonMesh& mesh = mesh_of(MeshFamily::quad).mesh;
  std::vector<char> connected(mesh.num_edges(), 1);
  std::set<int> on_line;
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const MeshEdge& edge = mesh.edge(e);
    if (edge.on_boundary()) continue;
    if (std::abs(mesh.vertex(edge.v0).x() - 0.5) < 1e-12 &&
        std::abs(mesh.vertex(edge.v1).x() - 0.5) < 1e-12) {
      connected[e] = 0;
      on_line.insert(edge.v0);
      on_line.insert(edge.v1);
    }
  }
  ASSERT_FALSE(on_line.empty());
  const SplitDofMap map(mesh, connected);
  EXPECT_EQ(map.num_nodes(), mesh.num_vertices() + static_cast<int>(on_line.size()));
  for (int v : on_line) EXPECT_EQ(map.vertex_nodes(v).size(), 2u) << "vertex " << v;
  for (int e = 0; e < mesh.num_edges(); ++e) {
    if (!mesh.edge(e).on_boundary()) {
      EXPECT_EQ(map.joins(mesh, e), bool(connected[e]));
    }
  }
}

TEST(SplitDofMap, ALoneSplitEdgeInsideTheBodyCannotOpen) {
  // Its end vertices are joined around through the connected edges: section 4's reason why a
  // crack must reach the boundary or another crack before it separates anything.
  const PolygonMesh& mesh = mesh_of(MeshFamily::quad).mesh;
  int inner = -1;
  for (int e = 0; e < mesh.num_edges() && inner < 0; ++e) {
    const MeshEdge& edge = mesh.edge(e);
    bool boundary_vertex = false;
    for (int v : {edge.v0, edge.v1})
      for (bool s : mesh.domain().sides_near(mesh.vertex(v), 1e-9)) boundary_vertex |= s;
    if (!edge.on_boundary() && !boundary_vertex) inner = e;
  }
  ASSERT_GE(inner, 0);
  std::vector<char> connected(mesh.num_edges(), 1);
  connected[inner] = 0;
  const SplitDofMap map(mesh, connected);
  EXPECT_EQ(map.num_nodes(), mesh.num_vertices());
  EXPECT_TRUE(map.joins(mesh, inner));
}

/// Whether two maps of one mesh have the same classes: a one-to-one node correspondence.
void expect_same_classes(const PolygonMesh& mesh, const SplitDofMap& a, const SplitDofMap& b) {
  ASSERT_EQ(a.num_nodes(), b.num_nodes());
  std::vector<int> a_of_b(b.num_nodes(), -1), b_of_a(a.num_nodes(), -1);
  for (int p = 0; p < mesh.offsets().back(); ++p) {
    const int i = a.pair_nodes()[p], j = b.pair_nodes()[p];
    if (a_of_b[j] < 0) a_of_b[j] = i;
    if (b_of_a[i] < 0) b_of_a[i] = j;
    ASSERT_EQ(a_of_b[j], i) << "pair " << p;
    ASSERT_EQ(b_of_a[i], j) << "pair " << p;
  }
}

/// The map's own indexes agree with its pair nodes: each node's pairs (increasing) and each
/// vertex's nodes (ascending).
void expect_consistent_indexes(const PolygonMesh& mesh, const SplitDofMap& map) {
  std::vector<std::vector<int>> pairs(map.num_nodes());
  std::vector<std::vector<int>> nodes(mesh.num_vertices());
  for (int p = 0; p < mesh.offsets().back(); ++p) {
    const int i = map.pair_nodes()[p], v = mesh.cell_vertex_list()[p];
    pairs[i].push_back(p);
    if (std::find(nodes[v].begin(), nodes[v].end(), i) == nodes[v].end()) nodes[v].push_back(i);
  }
  for (int i = 0; i < map.num_nodes(); ++i) {
    const auto listed = map.node_pairs(i);
    ASSERT_EQ(std::vector<int>(listed.begin(), listed.end()), pairs[i]) << "node " << i;
  }
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    std::sort(nodes[v].begin(), nodes[v].end());
    const auto listed = map.vertex_nodes(v);
    ASSERT_EQ(std::vector<int>(listed.begin(), listed.end()), nodes[v]) << "vertex " << v;
  }
}

TEST(SplitDofMap, DisconnectingEdgesGivesTheClassesBuiltFromScratch) {
  // Random batches of cracks, as fracture makes them: after each batch the updated map has the
  // constructor's classes, every old node keeps its number, the split-off ones are appended
  // with their sources, and the split lists every node whose pairs changed.
  for (MeshFamily f : {MeshFamily::rcp, MeshFamily::quad, MeshFamily::perturbed_hex}) {
    const PolygonMesh& mesh = mesh_of(f).mesh;
    Random random(31);
    std::vector<char> connected(mesh.num_edges(), 1);
    SplitDofMap map = SplitDofMap::continuous(mesh);
    for (int batch = 0; batch < 40; ++batch) {
      std::vector<int> cracks;
      for (int e = 0; e < mesh.num_edges(); ++e)
        if (connected[e] && random.uniform() < 0.03) cracks.push_back(e);
      for (int e : cracks) connected[e] = 0;
      const SplitDofMap before = map;
      const SplitDofMap::Split split = map.disconnect(mesh, connected, cracks);
      expect_same_classes(mesh, map, SplitDofMap(mesh, connected));
      expect_consistent_indexes(mesh, map);
      ASSERT_EQ(map.num_nodes() - before.num_nodes(), static_cast<int>(split.source.size()));
      for (int p = 0; p < mesh.offsets().back(); ++p) {
        const int was = before.pair_nodes()[p], now = map.pair_nodes()[p];
        if (now >= before.num_nodes()) {
          ASSERT_EQ(split.source[now - before.num_nodes()], was) << "pair " << p;
        } else {
          ASSERT_EQ(now, was) << "pair " << p;  // an old node's pairs keep its number
        }
        const bool changed =
            now != was || before.node_pairs(was).size() != map.node_pairs(was).size();
        if (changed) {
          ASSERT_TRUE(std::binary_search(split.nodes.begin(), split.nodes.end(), was) &&
                      std::binary_search(split.nodes.begin(), split.nodes.end(), now))
              << "pair " << p;
        }
      }
    }
    EXPECT_GT(map.num_nodes(), 2 * mesh.num_vertices());  // the batches split a good part
  }
}

TEST(SplitDofMap, RefusesADisconnectThatJoins) {
  // An interior edge whose removal splits a node (one that reaches the boundary).
  const PolygonMesh& mesh = mesh_of(MeshFamily::quad).mesh;
  std::vector<char> connected(mesh.num_edges(), 1);
  int inner = -1;
  for (int e = 0; e < mesh.num_edges() && inner < 0; ++e) {
    if (mesh.edge(e).on_boundary()) continue;
    connected[e] = 0;
    const SplitDofMap map(mesh, connected);
    if (map.num_nodes() > mesh.num_vertices()) inner = e;
    connected[e] = 1;
  }
  ASSERT_GE(inner, 0);
  connected[inner] = 0;
  SplitDofMap map(mesh, connected);
  connected[inner] = 1;  // turned back on: the classes at its ends would merge
  const std::vector<int> edges{inner};
  EXPECT_THROW(map.disconnect(mesh, connected, edges), InputError);
}

TEST(SplitDofMap, RefusesFlagsOfTheWrongLength) {
  const PolygonMesh& mesh = mesh_of(MeshFamily::quad).mesh;
  EXPECT_THROW(SplitDofMap(mesh, std::vector<char>(3, 1)), InputError);
}

}  // namespace
}  // namespace vorodg
