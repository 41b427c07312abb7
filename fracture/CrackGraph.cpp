#include "fracture/CrackGraph.hpp"

#include "core/util/Errors.hpp"
#include "core/util/UnionFind.hpp"

namespace vorodg {

CrackGraph::CrackGraph(const CrackState& cracks) {
  const PolygonMesh& mesh = cracks.mesh();
  UnionFind vertices(mesh.num_vertices());
  std::vector<char> on_crack(mesh.num_vertices(), 0);
  for (int e = 0; e < mesh.num_edges(); ++e) {
    if (!cracks.cracked(e)) continue;
    const MeshEdge& edge = mesh.edge(e);
    vertices.join(edge.v0, edge.v1);
    on_crack[edge.v0] = on_crack[edge.v1] = 1;
  }
  // Number only the classes that hold a cracked edge: uncracked vertices are singletons.
  int num_classes = 0;
  const std::vector<int> label = vertices.labels(&num_classes);
  std::vector<int> of_class(num_classes, -1);
  component_.assign(mesh.num_vertices(), -1);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (!on_crack[v]) continue;
    if (of_class[label[v]] < 0) of_class[label[v]] = num_components_++;
    component_[v] = of_class[label[v]];
  }
  edges_.assign(num_components_, 0);
  for (int e = 0; e < mesh.num_edges(); ++e)
    if (cracks.cracked(e)) ++edges_[component_[mesh.edge(e).v0]];
  sides_.assign(num_components_, {false, false, false, false});
  const double tol = mesh.tag_tolerance() * mesh.domain().scale();
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (component_[v] < 0) continue;
    const std::array<bool, 4> near = mesh.domain().sides_near(mesh.vertex(v), tol);
    for (int s = 0; s < 4; ++s) sides_[component_[v]][s] = sides_[component_[v]][s] || near[s];
  }
}

bool CrackGraph::touches(int k, Side s) const {
  if (s == Side::none) throw InputError("crack graph: side 'none' has no line");
  return sides_[k][static_cast<int>(s)];
}

bool CrackGraph::spans(Side a, Side b) const {
  if (a == Side::none || b == Side::none) throw InputError("crack graph: side 'none' has no line");
  for (int k = 0; k < num_components_; ++k)
    if (touches(k, a) && touches(k, b)) return true;
  return false;
}

}  // namespace vorodg
