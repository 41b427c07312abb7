#include "verification/problems/FractureProblem.hpp"

#include <cmath>
#include <map>

#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"

namespace vorodg {

FractureProblemKind parse_fracture_problem(const std::string& name) {
  if (name == "tension-bar") return FractureProblemKind::tension_bar;
  if (name == "three-point-bend") return FractureProblemKind::three_point_bend;
  throw InputError("problem '" + name + "': expected tension-bar or three-point-bend");
}

std::string fracture_problem_name(FractureProblemKind kind) {
  return kind == FractureProblemKind::tension_bar ? "tension-bar" : "three-point-bend";
}

void check_fracture_geometry(const FractureGeometry& g) {
  const Rectangle& d = g.domain;
  if (!(g.line_x > d.x0() && g.line_x < d.x1()))
    throw InputError("cracking.line = " + fmt(g.line_x) + ": expected inside the domain (" +
                     fmt(d.x0()) + ", " + fmt(d.x1()) + ")");
  if (!(g.notch_depth >= 0.0 && g.notch_depth < d.height()))
    throw InputError("notch_depth = " + fmt(g.notch_depth) + ": expected in [0, " +
                     fmt(d.height()) + ") (the beam's depth)");
  if (g.kind == FractureProblemKind::tension_bar && g.notch_depth != 0.0)
    throw InputError("notch_depth = " + fmt(g.notch_depth) + ": the tension bar has no notch");
}

namespace {

/// The vertex at p (within the mesh's tagging tolerance), or -1.
int vertex_at(const PolygonMesh& mesh, const Point& p) {
  const double tol = mesh.tag_tolerance() * mesh.domain().scale();
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if ((mesh.vertex(v) - p).norm() <= tol) return v;
  return -1;
}

/// Marks the interior edges on the crack line (above the notch) and in the notch; refuses a mesh
/// without edges along what the mode needs.
void mark_line_and_notch(const PolygonMesh& mesh, const FractureGeometry& g, double tol,
                         FractureSetup& s) {
  const Rectangle& d = g.domain;
  s.line.assign(mesh.num_edges(), 0);
  s.notch.assign(mesh.num_edges(), 0);
  const double notch_top = d.y0() + g.notch_depth;
  double line_length = 0.0, notch_length = 0.0;
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const MeshEdge& edge = mesh.edge(e);
    const Point &a = mesh.vertex(edge.v0), &b = mesh.vertex(edge.v1);
    if (edge.on_boundary() || std::abs(a.x() - g.line_x) > tol || std::abs(b.x() - g.line_x) > tol)
      continue;
    const bool in_notch = std::max(a.y(), b.y()) <= notch_top + tol;
    (in_notch ? s.notch : s.line)[e] = 1;
    (in_notch ? notch_length : line_length) += mesh.edge_length(e);
  }
  const bool needs_line =
      s.mode == CrackingMode::pre_inserted || s.mode == CrackingMode::restricted;
  if (needs_line && std::abs(line_length - (d.height() - g.notch_depth)) > 1e3 * tol)
    throw InputError("cracking.line = " + fmt(g.line_x) + ": the mesh has edges along only " +
                     fmt(line_length) + " of the " + fmt(d.height() - g.notch_depth) +
                     " the crack line needs (use a symmetric mesh)");
  if (std::abs(notch_length - g.notch_depth) > 1e3 * tol)
    throw InputError("notch_depth = " + fmt(g.notch_depth) + ": the mesh has edges along only " +
                     fmt(notch_length) + " of it at x = " + fmt(g.line_x));
}

/// The load point and the crack-mouth gauge: the beam's mouth vertex, or for the bar the mean
/// opening of the line (a gauge at one end would drive it to rotate).
void find_gauges(const PolygonMesh& mesh, const FractureGeometry& g, FractureSetup& s) {
  const Rectangle& d = g.domain;
  if (g.kind == FractureProblemKind::three_point_bend) {
    s.load_vertex = vertex_at(mesh, Point(g.line_x, d.y1()));
    if (s.load_vertex < 0)
      throw InputError("cracking.line = " + fmt(g.line_x) +
                       ": the mesh has no vertex at the load point (" + fmt(g.line_x) + ", " +
                       fmt(d.y1()) + ")");
    const int mouth = vertex_at(mesh, Point(g.line_x, d.y0()));
    if (mouth < 0)
      throw InputError("cracking.line = " + fmt(g.line_x) +
                       ": the mesh has no vertex at the crack mouth (" + fmt(g.line_x) + ", " +
                       fmt(d.y0()) + ")");
    s.mouth.vertices = {mouth};
    s.mouth.weights = {1.0};
    return;
  }
  std::map<int, double> weight;
  for (int e = 0; e < mesh.num_edges(); ++e)
    if (s.line[e])
      for (int v : {mesh.edge(e).v0, mesh.edge(e).v1})
        weight[v] += 0.5 * mesh.edge_length(e) / d.height();
  for (const auto& [v, w] : weight) {
    s.mouth.vertices.push_back(v);
    s.mouth.weights.push_back(w);
  }
}

/// The supports (the bar: pulled at its right end on rollers; the beam: simply supported) and
/// the beam's load point.
void add_constraints(const PolygonMesh& mesh, const FractureGeometry& g, double tol,
                     FractureSetup& s) {
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const auto near = g.domain.sides_near(mesh.vertex(v), tol);  // left, right, bottom, top
    if (g.kind == FractureProblemKind::tension_bar) {
      if (near[0]) s.constraints.push_back({v, 0, 0.0});
      if (near[1]) s.constraints.push_back({v, 0, 1.0});
      if (near[2]) s.constraints.push_back({v, 1, 0.0});  // rollers: see the header
    } else {
      if (near[0] && near[2]) s.constraints.push_back({v, 0, 0.0});
      if ((near[0] || near[1]) && near[2]) s.constraints.push_back({v, 1, 0.0});
    }
  }
  if (g.kind == FractureProblemKind::three_point_bend)
    s.constraints.push_back({s.load_vertex, 1, -1.0});
}

}  // namespace

MeshSpec fracture_mesh_spec(MeshSpec spec, const FractureGeometry& g) {
  if (spec.symmetric && g.notch_depth > 0.0) spec.line_marks = {g.domain.y0() + g.notch_depth};
  return spec;
}

FractureSetup fracture_setup(const PolygonMesh& mesh, const FractureGeometry& g, CrackingMode mode,
                             double thickness) {
  check_fracture_geometry(g);
  const double tol = mesh.tag_tolerance() * g.domain.scale();
  FractureSetup s;
  s.mode = mode;
  s.thickness = thickness;
  mark_line_and_notch(mesh, g, tol, s);
  find_gauges(mesh, g, s);
  add_constraints(mesh, g, tol, s);
  return s;
}

namespace {

/// The modulus of the bar in uniaxial stress (free to contract across its height).
double bar_modulus(const IsotropicElasticity& material) {
  return material.model() == PlaneModel::stress
             ? material.E()
             : material.E() / (1.0 - material.nu() * material.nu());
}

}  // namespace

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
