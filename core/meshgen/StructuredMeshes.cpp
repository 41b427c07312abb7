#include "core/meshgen/StructuredMeshes.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "core/meshgen/MeshFamily.hpp"
#include "core/meshgen/VoronoiTessellator.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "core/util/Random.hpp"

namespace vorodg {
namespace {

void check_size(const Rectangle& domain, double h, const char* what) {
  if (!(h > 0.0) || !std::isfinite(h))
    throw InputError(std::string(what) + " = " + fmt(h) + ": expected a finite value > 0");
  if (h > domain.scale())
    throw InputError(std::string(what) + " = " + fmt(h) +
                     ": expected no more than the domain's longer side " + fmt(domain.scale()));
  if (domain.area() / (h * h) > 1.5e8)
    throw InputError(std::string(what) + " = " + fmt(h) + ": gives more than 1.5e8 cells");
}

int hex_rows(const Rectangle& domain, double spacing) {
  const double row_height = spacing * std::numbers::sqrt3 / 2.0;
  return std::max(1, static_cast<int>(std::lround(domain.height() / row_height)));
}

double adjusted_spacing(const Rectangle& domain, double spacing) {
  return domain.height() / (hex_rows(domain, spacing) * std::numbers::sqrt3 / 2.0);
}

}  // namespace

PolygonMesh hex_mesh(const Rectangle& domain, double spacing) {
  check_size(domain, spacing, "hexagon spacing h");
  const int rows = hex_rows(domain, spacing);
  const double a = adjusted_spacing(domain, spacing);
  const double snap = 1e-9 * a;
  std::vector<Point> seeds;
  for (int j = 0; j <= rows; ++j) {
    const double y = (j == rows) ? domain.y1() : domain.y0() + j * domain.height() / rows;
    const double shift = (j % 2) ? 0.5 * a : 0.0;
    for (int i = 0;; ++i) {
      double x = domain.x0() + shift + i * a;
      if (std::abs(x - domain.x1()) <= snap) x = domain.x1();
      if (x > domain.x1()) break;
      seeds.emplace_back(x, y);
    }
  }
  return voronoi_mesh(domain, seeds, a);
}

PolygonMesh perturb_mesh(const PolygonMesh& mesh, double r, std::uint64_t seed) {
  if (!(r >= 0.0 && r < kMaxPerturbation))
    throw InputError("perturbation r = " + fmt(r) + ": expected 0 <= r < 0.5");
  const Rectangle& dom = mesh.domain();
  const double tol = mesh.tag_tolerance() * dom.scale();
  std::vector<double> shortest(mesh.num_vertices(), std::numeric_limits<double>::infinity());
  for (int e = 0; e < mesh.num_edges(); ++e)
    for (int v : {mesh.edge(e).v0, mesh.edge(e).v1})
      shortest[v] = std::min(shortest[v], mesh.edge_length(e));
  Random rng(seed);
  std::vector<Point> moved = mesh.vertices();
  for (std::size_t i = 0; i < moved.size(); ++i) {
    Point& p = moved[i];
    const double reach = r * shortest[i];
    const auto near = dom.sides_near(p, tol);
    const bool on_vertical = near[0] || near[1];
    const bool on_horizontal = near[2] || near[3];
    // Draw the same numbers for every vertex so one vertex's class does not shift the stream.
    const double u = rng.uniform(), v = rng.uniform();
    if (on_vertical && on_horizontal) continue;  // corners stay
    if (on_vertical) {
      p.y() = std::clamp(p.y() + reach * (2.0 * u - 1.0), dom.y0(), dom.y1());
    } else if (on_horizontal) {
      p.x() = std::clamp(p.x() + reach * (2.0 * u - 1.0), dom.x0(), dom.x1());
    } else {
      const double radius = reach * std::sqrt(u), angle = 2.0 * std::numbers::pi * v;
      p += radius * Point(std::cos(angle), std::sin(angle));
    }
  }
  return PolygonMesh(dom, std::move(moved), mesh.offsets(), mesh.cell_vertex_list(),
                     mesh.tag_tolerance());
}

PolygonMesh quad_mesh(const Rectangle& domain, double h) {
  check_size(domain, h, "quad edge length h");
  const int nx = std::max(1, static_cast<int>(std::lround(domain.width() / h)));
  const int ny = std::max(1, static_cast<int>(std::lround(domain.height() / h)));
  std::vector<Point> vertices;
  vertices.reserve(static_cast<std::size_t>(nx + 1) * (ny + 1));
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      vertices.emplace_back(i == nx ? domain.x1() : domain.x0() + i * domain.width() / nx,
                            j == ny ? domain.y1() : domain.y0() + j * domain.height() / ny);
  std::vector<int> offsets{0}, cells;
  cells.reserve(4 * static_cast<std::size_t>(nx) * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int v = j * (nx + 1) + i;
      cells.insert(cells.end(), {v, v + 1, v + nx + 2, v + nx + 1});
      offsets.push_back(static_cast<int>(cells.size()));
    }
  return PolygonMesh(domain, std::move(vertices), std::move(offsets), std::move(cells));
}

}  // namespace vorodg
