#include "core/meshgen/MeshFamily.hpp"

#include <algorithm>
#include <cmath>

#include "core/io/VtuMesh.hpp"
#include "core/mesh/MeshStatistics.hpp"
#include "core/mesh/MeshValidator.hpp"
#include "core/meshgen/MeshCompaction.hpp"
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

/// symmetric notch_only: where the mirrored seed pairs go and which vertices the line must get.
struct NotchLine {
  double x = 0.0;             // the domain's vertical mid-line
  std::vector<double> rows;   // heights of the seed pairs (x -+ d/2, row)
  std::vector<double> marks;  // vertices on the line: y0 + k s up to the notch tip, then y1
  int notch_marks = 0;        // the first this many marks are joined by edges (the notch)
};

/// Pairs k = 0..n at y0 + (k + 1/2) s, with s = depth / n <= d, put line vertices at y0 + k s,
/// mouth and tip included: each is the common circumcentre of two mirrored pairs (or of a pair
/// and its mirror image across the bottom). One more pair half a spacing below the top puts a
/// vertex at the load point. Without a notch only the mouth's pair and the top's pair remain.
NotchLine notch_line(const MeshSpec& spec) {
  const Rectangle& dom = spec.domain;
  const double d = spec.size;
  if (spec.line_marks.size() > 1)
    throw InputError("symmetric notch: expected at most one line mark (the notch tip), found " +
                     std::to_string(spec.line_marks.size()));
  const double tip = spec.line_marks.empty() ? dom.y0() : spec.line_marks.front();
  if (!(tip >= dom.y0() && tip < dom.y1()))
    throw InputError("symmetric notch: notch tip at height " + fmt(tip) + ": expected in [" +
                     fmt(dom.y0()) + ", " + fmt(dom.y1()) + ")");
  if (dom.width() < 4.0 * d)
    throw InputError("symmetric notch, d = " + fmt(d) + ": domain width " + fmt(dom.width()) +
                     ": expected at least 4 d = " + fmt(4.0 * d));
  if (dom.y1() - tip < 1.5 * d)  // room for the top's pair above the notch's last one
    throw InputError("symmetric notch, d = " + fmt(d) + ": ligament above the notch tip " +
                     fmt(dom.y1() - tip) + ": expected at least 1.5 d = " + fmt(1.5 * d) +
                     " (a smaller d or a shallower notch)");
  NotchLine line;
  line.x = 0.5 * (dom.x0() + dom.x1());
  const double depth = tip - dom.y0();
  const int n = depth > 0.0 ? std::max(1, static_cast<int>(std::ceil(depth / d - 1e-9))) : 0;
  const double s = n > 0 ? depth / n : d;
  for (int k = 0; k <= n; ++k) {
    line.rows.push_back(dom.y0() + (k + 0.5) * s);
    line.marks.push_back(k == n ? tip : dom.y0() + k * s);
  }
  line.notch_marks = n + 1;
  line.rows.push_back(dom.y1() - 0.5 * d);
  line.marks.push_back(dom.y1());
  return line;
}

/// The seeds without those closer than d to a pair, plus the pairs. Rows at most d apart with
/// offsets d/2 leave no point of the line between two rows farther than d / sqrt(2) from its
/// pairs, and no other seed can come that close without being within d of a pair: so the pairs
/// own the line there, and their bisectors, the line, are Voronoi edges.
std::vector<Point> with_notch_pairs(std::vector<Point> seeds, const NotchLine& line, double d) {
  std::vector<Point> pairs;
  for (double y : line.rows) {
    pairs.emplace_back(line.x - 0.5 * d, y);
    pairs.emplace_back(line.x + 0.5 * d, y);
  }
  const auto near_pair = [&](const Point& p) {
    return std::abs(p.x() - line.x) < 1.5 * d &&
           std::any_of(pairs.begin(), pairs.end(),
                       [&](const Point& q) { return (p - q).norm() < d; });
  };
  seeds.erase(std::remove_if(seeds.begin(), seeds.end(), near_pair), seeds.end());
  seeds.insert(seeds.end(), pairs.begin(), pairs.end());
  return seeds;
}

/// The pairs' bisectors are the line up to round-off: the vertices on it are put there exactly,
/// the marks' onto their heights. Regularization never reaches them (their edges are at least
/// about d/2 long), so a missing mark or notch edge is a breakdown, not bad input.
PolygonMesh snapped_to_notch_line(const PolygonMesh& mesh, const NotchLine& line, double d) {
  const double tol = 1e-9 * d;
  std::vector<Point> vertices = mesh.vertices();
  std::vector<int> at_mark(line.marks.size(), -1);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    Point& p = vertices[v];
    if (std::abs(p.x() - line.x) > tol) continue;
    p.x() = line.x;
    for (std::size_t k = 0; k < line.marks.size(); ++k)
      if (std::abs(p.y() - line.marks[k]) <= tol) p.y() = line.marks[k], at_mark[k] = v;
  }
  const auto missing = [&](std::size_t k, const std::string& what) {
    return NumericalError("symmetric notch: no " + what + " at (" + fmt(line.x) + ", " +
                          fmt(line.marks[k]) + ") on the crack line");
  };
  for (std::size_t k = 0; k < line.marks.size(); ++k)
    if (at_mark[k] < 0) throw missing(k, "vertex");
  for (int k = 0; k + 1 < line.notch_marks; ++k) {
    bool joined = false;
    for (int c : mesh.vertex_cells(at_mark[k]))
      for (int e : mesh.cell_edges(c))
        joined |= std::minmax(mesh.edge(e).v0, mesh.edge(e).v1) ==
                  std::minmax(at_mark[k], at_mark[k + 1]);
    if (!joined) throw missing(k, "notch edge upwards");
  }
  return PolygonMesh(mesh.domain(), std::move(vertices), mesh.offsets(), mesh.cell_vertex_list(),
                     mesh.tag_tolerance());
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
  options.threads = spec.threads;
  std::vector<Point> seeds = sample_poisson_disk(spec.domain, options).points;
  std::optional<NotchLine> notch;
  if (spec.symmetric && spec.notch_only) {
    notch = notch_line(spec);
    seeds = with_notch_pairs(std::move(seeds), *notch, spec.size);
  }
  out.report.seconds["seeding"] = clock.seconds();
  out.report.seeds = static_cast<int>(seeds.size());
  out.report.covered_fraction = covered_fraction(seeds.size(), spec.size, spec.domain.area());
  out.report.covered_fraction_interior = interior_fraction(spec.domain, seeds, spec.size);

  clock.restart();
  PolygonMesh raw = voronoi_mesh(spec.domain, seeds, spec.size);
  out.report.seconds["voronoi"] = clock.seconds();
  out.report.sides_before = side_count_histogram(raw);

  clock.restart();
  auto regular = regularize_mesh(raw, spec.regularization * spec.size);
  if (spec.regularization == 0.0)  // no collapses: merge what the validator calls one vertex
    regular.mesh = merge_coincident_vertices(
        regular.mesh, MeshValidationOptions{}.relative_tolerance * spec.domain.scale(),
        out.report.merged_vertices);
  out.report.seconds["regularization"] = clock.seconds();
  out.report.collapsed_edges = regular.collapsed_edges;
  out.report.refused_collapses = regular.refused_collapses;
  out.report.merged_cells = regular.merged_cells;
  out.mesh =
      notch ? snapped_to_notch_line(regular.mesh, *notch, spec.size) : std::move(regular.mesh);
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
  options.threads = spec.threads;
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
  if (spec.notch_only && !spec.symmetric)
    throw InputError("notch_only: mirrors part of a symmetric mesh, expected symmetric too");
  GeneratedMesh out;
  Stopwatch clock;
  switch (spec.family) {
    case MeshFamily::rcp:
      if (spec.symmetric && !spec.notch_only) {
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
