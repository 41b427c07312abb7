#include "core/meshgen/MeshFamily.hpp"

#include <algorithm>
#include <cmath>

#include "core/io/VtuMesh.hpp"
#include "core/mesh/MeshStatistics.hpp"
#include "core/meshgen/MeshRegularizer.hpp"
#include "core/meshgen/PoissonDiskSampler.hpp"
#include "core/meshgen/StructuredMeshes.hpp"
#include "core/meshgen/VoronoiTessellator.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "core/util/Random.hpp"

namespace vorodg {
namespace {

constexpr std::pair<MeshFamily, std::string_view> kFamilyNames[] = {
    {MeshFamily::rcp, "rcp"},
    {MeshFamily::hex, "hex"},
    {MeshFamily::perturbed_hex, "perturbed-hex"},
    {MeshFamily::tri, "tri"},
    {MeshFamily::quad, "quad"},
    {MeshFamily::file, "file"},
};

/// Covered fraction of the seeds at least 3d from every side, over the inset rectangle: the
/// sides crowd seeds (no neighbour beyond them), so the whole-domain fraction is higher.
std::optional<double> interior_fraction(const Rectangle& dom, const std::vector<Point>& seeds,
                                        double d) {
  const double margin = 3.0 * d;
  const double w = dom.width() - 2 * margin, h = dom.height() - 2 * margin;
  if (w <= 0 || h <= 0) return std::nullopt;
  std::size_t n = 0;
  for (const Point& p : seeds)
    if (p.x() >= dom.x0() + margin && p.x() <= dom.x1() - margin && p.y() >= dom.y0() + margin &&
        p.y() <= dom.y1() - margin)
      ++n;
  return covered_fraction(n, d, w * h);
}

GeneratedMesh generate_rcp(const MeshSpec& spec) {
  GeneratedMesh out;
  if (!(spec.regularization >= 0.0 && spec.regularization < kMaxRegularization))
    throw InputError("regularization threshold " + fmt(spec.regularization) +
                     ": expected a fraction of d in [0, 1)");
  Stopwatch clock;
  PoissonDiskOptions options;
  options.min_distance = spec.size;
  options.seed = spec.seed;
  const auto sample = sample_poisson_disk(spec.domain, options);
  out.report.seconds["seeding"] = clock.seconds();
  out.report.seeds = static_cast<int>(sample.points.size());
  out.report.covered_fraction =
      covered_fraction(sample.points.size(), spec.size, spec.domain.area());
  out.report.covered_fraction_interior = interior_fraction(spec.domain, sample.points, spec.size);

  clock.restart();
  PolygonMesh raw = voronoi_mesh(spec.domain, sample.points, spec.size);
  out.report.seconds["voronoi"] = clock.seconds();
  out.report.sides_before = side_count_histogram(raw);

  clock.restart();
  auto regular = regularize_mesh(raw, spec.regularization * spec.size);
  out.report.seconds["regularization"] = clock.seconds();
  out.report.collapsed_edges = regular.collapsed_edges;
  out.report.refused_collapses = regular.refused_collapses;
  out.report.merged_cells = regular.merged_cells;
  out.mesh = std::move(regular.mesh);
  return out;
}

/// The mesh and its mirror image about x = x_mid, glued along that line: vertices on it (which
/// the half mesh keeps on its side) are shared, and mirrored loops are reversed to stay
/// counter-clockwise.
PolygonMesh mirrored_about(const PolygonMesh& half, const Rectangle& whole,
                           const std::vector<double>& marks) {
  const double x_mid = half.domain().x1();
  const double tol = half.tag_tolerance() * half.domain().scale();
  std::vector<Point> vertices = half.vertices();
  for (double y : marks) {
    int nearest = -1;
    for (int v = 0; v < half.num_vertices(); ++v) {
      const Point& p = vertices[v];
      const bool inner = std::abs(p.x() - x_mid) <= tol && p.y() > half.domain().y0() + tol &&
                         p.y() < half.domain().y1() - tol;
      if (inner && (nearest < 0 || std::abs(p.y() - y) < std::abs(vertices[nearest].y() - y)))
        nearest = v;
    }
    if (nearest < 0)
      throw NumericalError("symmetric mesh: no vertex on the mid-line to move to height " + fmt(y));
    vertices[nearest].y() = y;
  }
  std::vector<int> image(half.num_vertices());
  for (int v = 0; v < half.num_vertices(); ++v) {
    const Point& p = half.vertex(v);
    if (std::abs(p.x() - x_mid) <= tol) {
      vertices[v].x() = x_mid;
      image[v] = v;
    } else {
      image[v] = static_cast<int>(vertices.size());
      vertices.emplace_back(2.0 * x_mid - p.x(), p.y());
    }
  }
  std::vector<int> offsets = half.offsets(), loops = half.cell_vertex_list();
  for (int c = 0; c < half.num_cells(); ++c) {
    const auto loop = half.cell_vertices(c);
    for (auto it = loop.rbegin(); it != loop.rend(); ++it) loops.push_back(image[*it]);
    offsets.push_back(static_cast<int>(loops.size()));
  }
  return PolygonMesh(whole, std::move(vertices), std::move(offsets), std::move(loops),
                     half.tag_tolerance());
}

GeneratedMesh generate_tri(const MeshSpec& spec) {
  GeneratedMesh out;
  Stopwatch clock;
  PoissonDiskOptions options;
  options.min_distance = spec.size;
  options.seed = spec.seed;
  options.fixed_points = sample_boundary_points(spec.domain, spec.size, derive_seed(spec.seed, 1));
  auto sample = sample_poisson_disk(spec.domain, options);
  // An interior seed close to a side, between two side seeds up to 2d apart, would make a
  // sliver; the side seeds cover that strip anyway.
  const auto n_fixed = static_cast<std::ptrdiff_t>(options.fixed_points.size());
  const auto near_side = [&](const Point& p) {
    for (int s = 0; s < 4; ++s)
      if (spec.domain.distance_to_side(p, static_cast<Side>(s)) < 0.5 * spec.size) return true;
    return false;
  };
  sample.points.erase(
      std::remove_if(sample.points.begin() + n_fixed, sample.points.end(), near_side),
      sample.points.end());
  out.report.seconds["seeding"] = clock.seconds();
  out.report.seeds = static_cast<int>(sample.points.size());
  clock.restart();
  out.mesh = delaunay_mesh(spec.domain, sample.points);
  out.report.seconds["delaunay"] = clock.seconds();
  return out;
}

}  // namespace

std::string_view family_name(MeshFamily f) {
  for (const auto& [family, name] : kFamilyNames)
    if (family == f) return name;
  return "?";
}

MeshFamily parse_family(const std::string& name) {
  std::string valid;
  for (const auto& [family, text] : kFamilyNames) {
    if (text == name) return family;
    valid += (valid.empty() ? "" : ", ") + std::string(text);
  }
  throw InputError("mesh family '" + name + "': expected one of " + valid);
}

GeneratedMesh generate_mesh(const MeshSpec& spec) {
  if (spec.symmetric && spec.family != MeshFamily::rcp)
    throw InputError("symmetric: only the rcp family is mirrored (found " +
                     std::string(family_name(spec.family)) + ")");
  GeneratedMesh out;
  Stopwatch clock;
  switch (spec.family) {
    case MeshFamily::rcp:
      if (spec.symmetric) {
        MeshSpec half = spec;
        half.domain = Rectangle(spec.domain.x0(), spec.domain.y0(),
                                0.5 * (spec.domain.x0() + spec.domain.x1()), spec.domain.y1());
        out = generate_rcp(half);
        out.mesh = mirrored_about(out.mesh, spec.domain, spec.line_marks);
      } else {
        out = generate_rcp(spec);
      }
      break;
    case MeshFamily::tri: out = generate_tri(spec); break;
    case MeshFamily::hex:
      out.mesh = hex_mesh(spec.domain, spec.size);
      out.report.seconds["hexagons"] = clock.seconds();
      break;
    case MeshFamily::perturbed_hex: {
      const PolygonMesh regular = hex_mesh(spec.domain, spec.size);
      out.mesh = perturb_mesh(regular, spec.perturbation, spec.seed);
      out.report.seconds["hexagons"] = clock.seconds();
      break;
    }
    case MeshFamily::quad:
      out.mesh = quad_mesh(spec.domain, spec.size);
      out.report.seconds["quads"] = clock.seconds();
      break;
    case MeshFamily::file:
      out.mesh = read_vtu(spec.path, spec.domain_given ? &spec.domain : nullptr);
      out.report.seconds["read"] = clock.seconds();
      break;
  }
  return out;
}

}  // namespace vorodg
