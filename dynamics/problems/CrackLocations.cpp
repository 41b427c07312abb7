#include "dynamics/problems/CrackLocations.hpp"

#include <algorithm>
#include <cmath>

namespace vorodg {

CrackLocations crack_locations(const PolygonMesh& mesh, const std::vector<int>& broken_edges,
                               const Rectangle& body, const Point& impact) {
  if (broken_edges.empty()) return {NAN, NAN, NAN};
  const bool tall = body.height() >= body.width();
  const double length = tall ? body.height() : body.width();
  const double start = tall ? body.lo().y() : body.lo().x();
  const double width = std::min(body.width(), body.height());
  double near = 0.0, middle = 0.0;
  for (int e : broken_edges) {
    const MeshEdge& edge = mesh.edge(e);
    const Point mid = 0.5 * (mesh.vertex(edge.v0) + mesh.vertex(edge.v1));
    const double along = ((tall ? mid.y() : mid.x()) - start) / length;
    if ((mid - impact).norm() < width)
      near += 1.0;
    else if (along > 1.0 / 3.0 && along < 2.0 / 3.0)
      middle += 1.0;
  }
  const double n = static_cast<double>(broken_edges.size());
  return {near / n, middle / n, (n - near - middle) / n};
}

}  // namespace vorodg
