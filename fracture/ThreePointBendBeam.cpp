// The notched three-point-bend beam (Petersson's, docs/fracture.md "Problems"): pinned at the
// lower-left corner, on a roller at the lower-right one, pushed down by the stroke at the top
// vertex above the crack line; a traction-free notch of depth notch_depth rises from the bottom
// along the line. The gauge is the crack mouth's vertex.
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "fracture/FractureProblem.hpp"

namespace vorodg {

namespace {

class ThreePointBendBeam final : public FractureProblem {
 public:
  std::string name() const override { return "three-point-bend"; }

  void find_gauges(const PolygonMesh& mesh, const FractureGeometry& g,
                   FractureSetup& s) const override {
    const Rectangle& d = g.domain;
    s.load_vertex = required_vertex(mesh, g, Point(g.line_x, d.y1()), "load point");
    s.mouth.vertices = {required_vertex(mesh, g, Point(g.line_x, d.y0()), "crack mouth")};
    s.mouth.weights = {1.0};
  }

  /// Simply supported (pinned left, roller right), the stroke down at the load point.
  void add_constraints(const PolygonMesh& mesh, const FractureGeometry& g, double tol,
                       FractureSetup& s) const override {
    for (int v = 0; v < mesh.num_vertices(); ++v) {
      const auto near = g.domain.sides_near(mesh.vertex(v), tol);  // left, right, bottom, top
      if (near[0] && near[2]) s.constraints.push_back({v, 0, 0.0});
      if ((near[0] || near[1]) && near[2]) s.constraints.push_back({v, 1, 0.0});
    }
    s.constraints.push_back({s.load_vertex, 1, -1.0});
  }

 private:
  static int required_vertex(const PolygonMesh& mesh, const FractureGeometry& g, const Point& p,
                             const std::string& what) {
    const int v = mesh_vertex_at(mesh, p);
    if (v < 0)
      throw InputError("cracking.line = " + fmt(g.line_x) + ": the mesh has no vertex at the " +
                       what + " (" + fmt(p.x()) + ", " + fmt(p.y()) + ")");
    return v;
  }
};

}  // namespace

std::shared_ptr<const FractureProblem> make_three_point_bend_beam() {
  return std::make_shared<ThreePointBendBeam>();
}

}  // namespace vorodg
