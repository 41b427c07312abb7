#include "core/meshgen/VoronoiTessellator.hpp"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <map>
#include <numeric>
#include <tuple>

#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"

namespace vorodg {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using FaceBase = CGAL::Triangulation_face_base_with_info_2<int, Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Tds>;
using CgalPoint = Kernel::Point_2;

// Seeds closer than this (times the domain size) to a side count as lying on it.
constexpr double kOnSide = 1e-14;

/// Original seeds (info = index) plus their mirror images across nearby sides and corners
/// (info = -1). A seed lying on a side is its own mirror there and is not mirrored across it.
std::vector<std::pair<CgalPoint, int>> seeds_with_mirrors(const Rectangle& domain,
                                                          const std::vector<Point>& seeds,
                                                          double spacing) {
  const double reach = 3.0 * spacing;
  const double on_side = kOnSide * domain.scale();
  std::vector<std::pair<CgalPoint, int>> pts;
  pts.reserve(seeds.size() + seeds.size() / 4 + 16);
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    const Point& p = seeds[i];
    pts.emplace_back(CgalPoint(p.x(), p.y()), static_cast<int>(i));
    // Mirror coordinates per axis: which reflections of x and of y are wanted.
    double xs[3] = {p.x(), 0, 0}, ys[3] = {p.y(), 0, 0};
    int nx = 1, ny = 1;
    const double dl = p.x() - domain.x0(), dr = domain.x1() - p.x();
    const double db = p.y() - domain.y0(), dt = domain.y1() - p.y();
    if (dl > on_side && dl < reach) xs[nx++] = 2.0 * domain.x0() - p.x();
    if (dr > on_side && dr < reach) xs[nx++] = 2.0 * domain.x1() - p.x();
    if (db > on_side && db < reach) ys[ny++] = 2.0 * domain.y0() - p.y();
    if (dt > on_side && dt < reach) ys[ny++] = 2.0 * domain.y1() - p.y();
    for (int a = 0; a < nx; ++a)
      for (int b = 0; b < ny; ++b)
        if (a > 0 || b > 0) pts.emplace_back(CgalPoint(xs[a], ys[b]), -1);
  }
  return pts;
}

/// Clips vertex loops (ids of circumcentres) to one side of the rectangle at a time. A crossing
/// vertex is created once per (Voronoi edge, side), so the two cells sharing a clipped edge share
/// its new end point exactly.
class SideClipper {
 public:
  SideClipper(const Rectangle& domain, const std::vector<Point>& centres, double tol)
      : domain_(domain), centres_(centres), tol_(tol) {}

  Point position(int id) const {
    const int n = static_cast<int>(centres_.size());
    return id < n ? centres_[id] : crossings_[id - n];
  }
  Point snapped_position(int id) const { return domain_.snap(position(id), tol_); }

  void clip(std::vector<int>& loop, Side side) {
    std::vector<int> out;
    const std::size_t n = loop.size();
    for (std::size_t k = 0; k < n; ++k) {
      const int a = loop[k], b = loop[(k + 1) % n];
      const double da = inward_distance(position(a), side);
      const double db = inward_distance(position(b), side);
      if (da >= -tol_) out.push_back(a);
      if ((da > tol_ && db < -tol_) || (da < -tol_ && db > tol_))
        out.push_back(crossing(a, b, side));
    }
    loop.swap(out);
  }

 private:
  double inward_distance(const Point& p, Side side) const {
    switch (side) {
      case Side::left: return p.x() - domain_.x0();
      case Side::right: return domain_.x1() - p.x();
      case Side::bottom: return p.y() - domain_.y0();
      default: return domain_.y1() - p.y();
    }
  }
  int crossing(int a, int b, Side side) {
    const auto key = std::make_tuple(std::min(a, b), std::max(a, b), static_cast<int>(side));
    if (auto it = ids_.find(key); it != ids_.end()) return it->second;
    const Point p = position(std::min(a, b)), q = position(std::max(a, b));
    const double dp = inward_distance(p, side), dq = inward_distance(q, side);
    Point x = p + (dp / (dp - dq)) * (q - p);
    if (side == Side::left || side == Side::right)
      x.x() = domain_.side_coordinate(side);
    else
      x.y() = domain_.side_coordinate(side);
    const int id = static_cast<int>(centres_.size() + crossings_.size());
    crossings_.push_back(x);
    ids_.emplace(key, id);
    return id;
  }

  const Rectangle& domain_;
  const std::vector<Point>& centres_;
  double tol_;
  std::vector<Point> crossings_;
  std::map<std::tuple<int, int, int>, int> ids_;
};

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

/// Each seed's Voronoi cell as the loop of the circumcentres of the Delaunay faces around it
/// (CSR: offsets, then face indices into centres), each circumcentre computed once.
struct CircumcentreLoops {
  std::vector<Point> centres;
  std::vector<int> offsets{0};
  std::vector<int> faces;
};

CircumcentreLoops circumcentre_loops(Delaunay& dt, std::size_t num_seeds) {
  std::vector<Delaunay::Vertex_handle> seed_vertex(num_seeds);
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
    if (v->info() >= 0) seed_vertex[v->info()] = v;
  for (auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f) f->info() = -1;
  CircumcentreLoops loops;
  loops.centres.reserve(2 * num_seeds + 64);
  loops.faces.reserve(6 * num_seeds);
  for (std::size_t i = 0; i < num_seeds; ++i) {
    auto start = dt.incident_faces(seed_vertex[i]);
    auto f = start;
    do {
      if (dt.is_infinite(f))
        throw NumericalError("Voronoi tessellation: the cell of seed " + std::to_string(i) +
                             " is unbounded; the seeds do not fill the domain");
      if (f->info() < 0) {
        f->info() = static_cast<int>(loops.centres.size());
        const CgalPoint c = dt.circumcenter(f);
        loops.centres.emplace_back(c.x(), c.y());
      }
      loops.faces.push_back(f->info());
    } while (++f != start);
    loops.offsets.push_back(static_cast<int>(loops.faces.size()));
  }
  return loops;
}

/// Coinciding circumcentres merged (a union-find forest: find_root gives each its survivor).
/// Co-circular seeds (every seed with its mirror and a neighbour's mirror pair, or a seed at a
/// corner) give zero-length Voronoi edges.
std::vector<int> merged_centres(const CircumcentreLoops& loops, double merge_tol) {
  std::vector<int> parent(loops.centres.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (std::size_t c = 0; c + 1 < loops.offsets.size(); ++c) {
    const int n = loops.offsets[c + 1] - loops.offsets[c];
    for (int k = 0; k < n; ++k) {
      const int a = loops.faces[loops.offsets[c] + k];
      const int b = loops.faces[loops.offsets[c] + (k + 1) % n];
      if ((loops.centres[a] - loops.centres[b]).norm() <= merge_tol)
        parent[find_root(parent, a)] = find_root(parent, b);
    }
  }
  return parent;
}

}  // namespace

PolygonMesh voronoi_mesh(const Rectangle& domain, const std::vector<Point>& seeds, double spacing) {
  if (seeds.empty()) throw InputError("Voronoi tessellation: no seeds");
  for (const Point& p : seeds)
    if (!domain.contains(p, 0.0))
      throw InputError("Voronoi tessellation: seed (" + fmt(p.x()) + "," + fmt(p.y()) +
                       ") lies outside the domain " + domain.to_string());
  auto pts = seeds_with_mirrors(domain, seeds, spacing);
  Delaunay dt;
  dt.insert(pts.begin(), pts.end());  // spatially sorted insertion
  if (static_cast<std::size_t>(dt.number_of_vertices()) != pts.size())
    throw InputError("Voronoi tessellation: two seeds coincide");

  const CircumcentreLoops loops = circumcentre_loops(dt, seeds.size());
  const std::vector<Point>& centres = loops.centres;
  const std::vector<int>& offsets = loops.offsets;
  const std::vector<int>& loop_faces = loops.faces;
  std::vector<int> parent = merged_centres(loops, 1e-9 * spacing);
  // Number the surviving vertices and rebuild the loops without repeats. The cell of a seed
  // lying on a side (not mirrored there: it is its own mirror) straddles the side symmetrically
  // and is clipped to it.
  SideClipper clipper(domain, centres, 1e-9 * spacing);
  std::vector<int> vertex_id(centres.size(), -1);
  std::vector<Point> vertices;
  vertices.reserve(centres.size());
  std::vector<int> cells;
  cells.reserve(loop_faces.size());
  std::vector<int> cell_offsets{0};
  std::vector<int> loop;
  for (std::size_t c = 0; c + 1 < offsets.size(); ++c) {
    loop.clear();
    for (int k = offsets[c]; k < offsets[c + 1]; ++k) {
      const int root = find_root(parent, loop_faces[k]);
      if (loop.empty() || loop.back() != root) loop.push_back(root);
    }
    while (loop.size() > 1 && loop.back() == loop.front()) loop.pop_back();
    for (int side = 0; side < 4; ++side)
      if (domain.distance_to_side(seeds[c], static_cast<Side>(side)) <= kOnSide * domain.scale())
        clipper.clip(loop, static_cast<Side>(side));
    for (int id : loop) {
      if (id >= static_cast<int>(vertex_id.size())) vertex_id.resize(id + 1, -1);
      if (vertex_id[id] < 0) {
        vertex_id[id] = static_cast<int>(vertices.size());
        vertices.push_back(clipper.snapped_position(id));
      }
      cells.push_back(vertex_id[id]);
    }
    cell_offsets.push_back(static_cast<int>(cells.size()));
  }
  return PolygonMesh(domain, std::move(vertices), std::move(cell_offsets), std::move(cells));
}

PolygonMesh delaunay_mesh(const Rectangle& domain, const std::vector<Point>& seeds) {
  std::vector<std::pair<CgalPoint, int>> pts;
  pts.reserve(seeds.size());
  for (std::size_t i = 0; i < seeds.size(); ++i)
    pts.emplace_back(CgalPoint(seeds[i].x(), seeds[i].y()), static_cast<int>(i));
  Delaunay dt;
  dt.insert(pts.begin(), pts.end());
  if (static_cast<std::size_t>(dt.number_of_vertices()) != seeds.size())
    throw InputError("Delaunay triangulation: two seeds coincide");
  std::vector<int> offsets{0};
  std::vector<int> cells;
  cells.reserve(6 * seeds.size());
  // Faces in a deterministic order: sorted by their smallest vertex index, then the others.
  std::vector<std::array<int, 3>> faces;
  faces.reserve(2 * seeds.size());
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    std::array<int, 3> t = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    faces.push_back(t);
  }
  std::sort(faces.begin(), faces.end());
  for (const auto& t : faces) {
    cells.insert(cells.end(), t.begin(), t.end());
    offsets.push_back(static_cast<int>(cells.size()));
  }
  std::vector<Point> vertices = seeds;
  return PolygonMesh(domain, std::move(vertices), std::move(offsets), std::move(cells));
}

}  // namespace vorodg
