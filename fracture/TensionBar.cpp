#include "fracture/TensionBar.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace vorodg {

namespace {

/// The modulus of the bar in uniaxial stress (free to contract across its height).
double bar_modulus(const IsotropicElasticity& material) {
  return material.model() == PlaneModel::stress
             ? material.E()
             : material.E() / (1.0 - material.nu() * material.nu());
}

class TensionBar final : public FractureProblem {
 public:
  std::string name() const override { return "tension-bar"; }
  bool takes_notch() const override { return false; }

  /// No load point; the gauge is the mean opening of the line (a gauge at one end would drive
  /// the bar to rotate).
  void find_gauges(const PolygonMesh& mesh, const FractureGeometry& g,
                   FractureSetup& s) const override {
    std::map<int, double> weight;
    for (int e = 0; e < mesh.num_edges(); ++e)
      if (s.line[e])
        for (int v : {mesh.edge(e).v0, mesh.edge(e).v1})
          weight[v] += 0.5 * mesh.edge_length(e) / g.domain.height();
    for (const auto& [v, w] : weight) {
      s.mouth.vertices.push_back(v);
      s.mouth.weights.push_back(w);
    }
  }

  /// Pulled at its right end, on rollers along the bottom (see the header).
  void add_constraints(const PolygonMesh& mesh, const FractureGeometry& g, double tol,
                       FractureSetup& s) const override {
    for (int v = 0; v < mesh.num_vertices(); ++v) {
      const auto near = g.domain.sides_near(mesh.vertex(v), tol);  // left, right, bottom, top
      if (near[0]) s.constraints.push_back({v, 0, 0.0});
      if (near[1]) s.constraints.push_back({v, 0, 1.0});
      if (near[2]) s.constraints.push_back({v, 1, 0.0});
    }
  }

  std::optional<double> closed_form_deviation(const FractureGeometry& g,
                                              const IsotropicElasticity& material,
                                              const CohesiveLaw& law, double thickness,
                                              double stroke, double opening,
                                              double load) const override {
    return tension_bar_deviation(g, material, law, thickness, stroke, opening, load);
  }
};

}  // namespace

std::shared_ptr<const FractureProblem> make_tension_bar() {
  return std::make_shared<TensionBar>();
}

BarResponse tension_bar_closed_form(const FractureGeometry& g, const IsotropicElasticity& material,
                                    const CohesiveLaw& law, double thickness, double opening) {
  const double sigma = law.envelope(opening);
  return {sigma * g.domain.width() / bar_modulus(material) + opening,
          sigma * g.domain.height() * thickness};
}

double tension_bar_deviation(const FractureGeometry& g, const IsotropicElasticity& material,
                             const CohesiveLaw& law, double thickness, double stroke,
                             double opening, double load) {
  const double peak = law.parameters().strength * g.domain.height() * thickness;
  if (opening <= kIntactOpening * law.critical_opening()) {  // the gauge reads round-off
    const double elastic =
        bar_modulus(material) * stroke / g.domain.width() * peak / law.parameters().strength;
    return std::abs(load - elastic) / peak;
  }
  const BarResponse cf = tension_bar_closed_form(g, material, law, thickness, opening);
  return std::max(std::abs(load - cf.load) / peak, std::abs(stroke - cf.stroke) / cf.stroke);
}

}  // namespace vorodg
