// The split DOF map's two ends and a line between them: all edges connected is the continuous
// space (a node per vertex), none the discontinuous one (a node per cell corner), and a straight
// line of split edges doubles exactly the vertices strictly inside the domain on it, plus the two
// on its ends at the boundary; disconnecting edges batch by batch gives the map built from
// scratch.
#include <gtest/gtest.h>

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

TEST(SplitDofMap, DisconnectingEdgesGivesTheMapBuiltFromScratch) {
  // Random batches of cracks, as fracture makes them: after each batch the updated map must be
  // the constructor's, node for node, and so must every vertex's node list.
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
      map.disconnect(mesh, connected, cracks);
      const SplitDofMap fresh(mesh, connected);
      ASSERT_EQ(map.num_nodes(), fresh.num_nodes()) << "batch " << batch;
      for (int c = 0; c < mesh.num_cells(); ++c)
        for (int k = 0; k < mesh.cell_size(c); ++k)
          ASSERT_EQ(map.node(c, k), fresh.node(c, k)) << "cell " << c << ", vertex " << k;
      for (int v = 0; v < mesh.num_vertices(); ++v) {
        const auto a = map.vertex_nodes(v), b = fresh.vertex_nodes(v);
        ASSERT_EQ(std::vector<int>(a.begin(), a.end()), std::vector<int>(b.begin(), b.end()));
      }
    }
    EXPECT_GT(map.num_nodes(), 2 * mesh.num_vertices());  // the batches split a good part
  }
}

TEST(SplitDofMap, RefusesFlagsOfTheWrongLength) {
  const PolygonMesh& mesh = mesh_of(MeshFamily::quad).mesh;
  EXPECT_THROW(SplitDofMap(mesh, std::vector<char>(3, 1)), InputError);
}

}  // namespace
}  // namespace vorodg
