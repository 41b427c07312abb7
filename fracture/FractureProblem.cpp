#include "fracture/FractureProblem.hpp"

#include <cmath>

#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"

namespace vorodg {

// The shipped problems, one file each.
std::shared_ptr<const FractureProblem> make_tension_bar();
std::shared_ptr<const FractureProblem> make_three_point_bend_beam();

const std::vector<std::shared_ptr<const FractureProblem>>& fracture_problems() {
  static const std::vector<std::shared_ptr<const FractureProblem>> problems{
      make_tension_bar(), make_three_point_bend_beam()};
  return problems;
}

std::shared_ptr<const FractureProblem> fracture_problem(const std::string& name) {
  for (const auto& p : fracture_problems())
    if (p->name() == name) return p;
  throw InputError("problem '" + name + "': expected " + fracture_problem_list());
}

std::string fracture_problem_list() {
  struct Named {
    std::string name;
  };
  std::vector<Named> names;
  for (const auto& p : fracture_problems()) names.push_back({p->name()});
  return name_list(names);
}

std::string fracture_problem_words() {
  std::string words = " ";
  for (const auto& p : fracture_problems()) words += p->name() + " ";
  return words;
}

int mesh_vertex_at(const PolygonMesh& mesh, const Point& p) {
  const double tol = mesh.tag_tolerance() * mesh.domain().scale();
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if ((mesh.vertex(v) - p).norm() <= tol) return v;
  return -1;
}

void check_fracture_geometry(const FractureGeometry& g) {
  const Rectangle& d = g.domain;
  if (!(g.line_x > d.x0() && g.line_x < d.x1()))
    throw InputError("cracking.line = " + fmt(g.line_x) + ": expected inside the domain (" +
                     fmt(d.x0()) + ", " + fmt(d.x1()) + ")");
  if (!(g.notch_depth >= 0.0 && g.notch_depth < d.height()))
    throw InputError("notch_depth = " + fmt(g.notch_depth) + ": expected in [0, " +
                     fmt(d.height()) + ") (the beam's depth)");
  if (!g.problem->takes_notch() && g.notch_depth != 0.0)
    throw InputError("notch_depth = " + fmt(g.notch_depth) + ": the " + g.problem->name() +
                     " has no notch");
}

namespace {

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
  g.problem->find_gauges(mesh, g, s);
  g.problem->add_constraints(mesh, g, tol, s);
  return s;
}

}  // namespace vorodg
