#include "core/mesh/MeshValidator.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "core/geometry/Polygon.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"

namespace vorodg {
namespace {

class DefectList {
 public:
  DefectList(MeshValidationReport& report, int max_reported)
      : report_(report), max_(max_reported) {}
  void add(MeshDefect::Kind kind, int index, std::string what) {
    ++report_.defect_count;
    if (static_cast<int>(report_.defects.size()) < max_)
      report_.defects.push_back({kind, index, std::move(what)});
  }

 private:
  MeshValidationReport& report_;
  int max_;
};

std::string cell_name(int c) {
  return "cell " + std::to_string(c);
}

void check_vertices(const PolygonMesh& mesh, double tol, DefectList& out) {
  const int n = mesh.num_vertices();
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return mesh.vertex(a).x() < mesh.vertex(b).x(); });
  for (int i = 0; i < n; ++i) {
    const Point& p = mesh.vertex(order[i]);
    for (int j = i + 1; j < n && mesh.vertex(order[j]).x() - p.x() <= tol; ++j) {
      if (std::abs(mesh.vertex(order[j]).y() - p.y()) <= tol) {
        const int a = std::min(order[i], order[j]), b = std::max(order[i], order[j]);
        out.add(MeshDefect::Kind::duplicate_vertex, b,
                "vertex " + std::to_string(b) + " duplicates vertex " + std::to_string(a) +
                    " at (" + fmt(p.x()) + "," + fmt(p.y()) + "), expected distinct positions");
      }
    }
  }
  for (int v = 0; v < n; ++v)
    if (mesh.vertex_cells(v).empty())
      out.add(MeshDefect::Kind::unreferenced_vertex, v,
              "vertex " + std::to_string(v) + " belongs to no cell");
}

void check_cell(const PolygonMesh& mesh, int c, double tol, double min_area, DefectList& out) {
  const auto ids = mesh.cell_vertices(c);
  std::vector<int> sorted(ids.begin(), ids.end());
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
    out.add(MeshDefect::Kind::repeated_vertex_in_cell, c,
            cell_name(c) + " lists a vertex more than once, expected a simple loop");
    return;
  }
  const auto pts = mesh.cell_points(c);
  for (std::size_t k = 0; k < pts.size(); ++k)
    if (!mesh.domain().contains(pts[k], tol)) {
      out.add(MeshDefect::Kind::cell_outside_domain, c,
              cell_name(c) + " has vertex " + std::to_string(ids[k]) + " at (" + fmt(pts[k].x()) +
                  "," + fmt(pts[k].y()) + ") outside the domain " + mesh.domain().to_string());
      break;
    }
  const double area = polygon::signed_area(pts);
  if (!std::isfinite(area) || std::abs(area) <= min_area) {  // not finite: coordinates overflow
    out.add(MeshDefect::Kind::zero_area_cell, c,
            cell_name(c) + " has area " + fmt(area) + ", expected a finite area above " +
                fmt(min_area));
    return;
  }
  if (polygon::self_intersects(pts)) {
    out.add(MeshDefect::Kind::self_intersecting_cell, c,
            cell_name(c) + " is self-intersecting, expected a simple polygon");
    return;
  }
  if (area < 0) {
    out.add(
        MeshDefect::Kind::clockwise_cell, c,
        cell_name(c) + " is clockwise (signed area " + fmt(area) + "), expected counter-clockwise");
    return;
  }
  // Fan quadrature and the RK element need every fan triangle from the centroid positive.
  const Point centroid = polygon::centroid(pts, area);
  if (!centroid.allFinite()) {  // a NaN centroid would pass the test below
    out.add(MeshDefect::Kind::not_star_shaped, c,
            cell_name(c) + " has centroid (" + fmt(centroid.x()) + "," + fmt(centroid.y()) +
                "), expected finite coordinates (the cell is too large for double precision)");
    return;
  }
  if (!polygon::star_shaped_about(pts, centroid, 0.0))
    out.add(MeshDefect::Kind::not_star_shaped, c,
            cell_name(c) + " is not star-shaped with respect to its centroid");
}

void check_edges(const PolygonMesh& mesh, DefectList& out) {
  for (const TopologyDefect& t : mesh.topology_defects()) {
    switch (t.kind) {
      case TopologyDefect::Kind::non_manifold_edge:
        out.add(MeshDefect::Kind::non_manifold_edge, t.v0, t.what);
        break;
      case TopologyDefect::Kind::inconsistent_orientation:
        out.add(MeshDefect::Kind::inconsistent_orientation, t.v0, t.what);
        break;
      case TopologyDefect::Kind::degenerate_edge:
        out.add(MeshDefect::Kind::repeated_vertex_in_cell, t.v0, t.what);
        break;
    }
  }
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const MeshEdge& edge = mesh.edge(e);
    if (edge.on_boundary() && edge.side == Side::none)
      out.add(MeshDefect::Kind::boundary_edge_off_domain, e,
              "edge " + std::to_string(e) + " (" + std::to_string(edge.v0) + "," +
                  std::to_string(edge.v1) + ") of " + cell_name(edge.cell0) +
                  " has no neighbour but lies on no side of the domain (a hole or a gap)");
  }
}

}  // namespace

std::string_view defect_kind_name(MeshDefect::Kind kind) {
  using K = MeshDefect::Kind;
  switch (kind) {
    case K::empty_mesh: return "empty mesh";
    case K::duplicate_vertex: return "duplicate vertex";
    case K::unreferenced_vertex: return "unreferenced vertex";
    case K::repeated_vertex_in_cell: return "repeated vertex in cell";
    case K::clockwise_cell: return "clockwise cell";
    case K::zero_area_cell: return "zero-area cell";
    case K::self_intersecting_cell: return "self-intersecting cell";
    case K::not_star_shaped: return "cell not star-shaped";
    case K::cell_outside_domain: return "cell outside domain";
    case K::non_manifold_edge: return "non-manifold edge";
    case K::inconsistent_orientation: return "inconsistent orientation";
    case K::boundary_edge_off_domain: return "boundary edge off domain";
    case K::area_mismatch: return "area mismatch";
  }
  return "?";
}

std::string MeshValidationReport::summary() const {
  std::ostringstream os;
  for (const MeshDefect& d : defects) os << defect_kind_name(d.kind) << ": " << d.what << '\n';
  if (defect_count > static_cast<int>(defects.size()))
    os << "... and " << defect_count - static_cast<int>(defects.size()) << " more defects\n";
  return os.str();
}

MeshValidationReport validate_mesh(const PolygonMesh& mesh, const MeshValidationOptions& options) {
  MeshValidationReport report;
  DefectList out(report, options.max_reported);
  if (mesh.num_cells() == 0) {
    out.add(MeshDefect::Kind::empty_mesh, -1, "the mesh has no cells");
    return report;
  }
  // Sizes and areas must be finite for every tolerance below (a NaN comparison passes).
  const Rectangle& domain = mesh.domain();
  if (!std::isfinite(domain.area()) || !(domain.area() > 0)) {
    out.add(MeshDefect::Kind::area_mismatch, -1,
            "the domain " + domain.to_string() + " has area " + fmt(domain.area()) +
                ", expected a finite positive area (coordinates too large or too small for double "
                "precision)");
    return report;
  }
  const double tol = options.relative_tolerance * mesh.domain().scale();
  const double h = mesh.h_avg();
  const double min_area = options.relative_min_area * h * h;
  check_vertices(mesh, tol, out);
  for (int c = 0; c < mesh.num_cells(); ++c) check_cell(mesh, c, tol, min_area, out);
  check_edges(mesh, out);
  const double area = mesh.total_area();
  const double domain_area = mesh.domain().area();
  const double mismatch = std::abs(area - domain_area) / domain_area;
  if (!(mismatch <= options.relative_area_tolerance))  // NaN (an infinite cell area) fails too
    out.add(MeshDefect::Kind::area_mismatch, -1,
            "cells cover area " + fmt(area) + ", expected the domain's " + fmt(domain_area) +
                " (relative difference " + fmt(mismatch) + ": " +
                (area < domain_area ? "holes" : "overlaps") + ")");
  return report;
}

void require_valid_mesh(const PolygonMesh& mesh, const std::string& what) {
  const MeshValidationReport report = validate_mesh(mesh);
  if (report.ok()) return;
  throw InputError(what + " is invalid: " + report.defects.front().what + " (" +
                   std::to_string(report.defect_count) + " defects; see vorodg mesh --check)");
}

}  // namespace vorodg
