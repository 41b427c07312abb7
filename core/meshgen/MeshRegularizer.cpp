#include "core/meshgen/MeshRegularizer.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <queue>
#include <span>
#include <tuple>

#include "core/geometry/Polygon.hpp"
#include "core/meshgen/MeshCompaction.hpp"

namespace vorodg {
namespace {

// A corner counts as reflex when it bends the wrong way by more than this (relative).
constexpr double kConvexTolerance = 1e-9;
constexpr unsigned kLeft = 1u, kRight = 2u, kBottom = 4u, kTop = 8u;

// Mutable copy of a mesh in which edges collapse: cells keep their CSR slots and shrink in place,
// merged vertices form union-find classes whose cells are the union of their members' cells.
class CollapsibleMesh {
 public:
  CollapsibleMesh(const PolygonMesh& mesh, double threshold)
      : mesh_(mesh),
        threshold_(threshold),
        pos_(mesh.vertices()),
        loop_(mesh.cell_vertex_list()),
        len_(mesh.num_cells()),
        parent_(mesh.num_vertices()),
        next_member_(mesh.num_vertices(), -1),
        last_member_(mesh.num_vertices()),
        sides_(mesh.num_vertices(), 0u) {
    for (int c = 0; c < mesh.num_cells(); ++c) len_[c] = mesh.cell_size(c);
    const double tol = mesh.tag_tolerance() * mesh.domain().scale();
    for (int v = 0; v < mesh.num_vertices(); ++v) {
      parent_[v] = last_member_[v] = v;
      const auto near = mesh.domain().sides_near(pos_[v], tol);
      for (int s = 0; s < 4; ++s)
        if (near[s]) sides_[v] |= 1u << s;
    }
    min_fan_area_ = 1e-12 * threshold * threshold;
  }

  int root(int v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  }
  double length(int a, int b) const { return (pos_[a] - pos_[b]).norm(); }

  /// Tries to merge b into a; returns false (and changes nothing) if the result would be invalid
  /// or leave a cell with fewer than `min_sides` sides.
  bool try_collapse(int a, int b, int min_sides);
  int cell_size(int c) const { return len_[c]; }
  /// Edges of cell c as (length, smaller vertex, larger vertex), shortest first.
  std::vector<std::tuple<double, int, int>> edges_by_length(int c) const {
    std::vector<std::tuple<double, int, int>> edges;
    const int* loop = &loop_[mesh_.offsets()[c]];
    for (int k = 0; k < len_[c]; ++k) {
      const int a = loop[k], b = loop[(k + 1) % len_[c]];
      edges.emplace_back(length(a, b), std::min(a, b), std::max(a, b));
    }
    std::sort(edges.begin(), edges.end());
    return edges;
  }
  /// Pushes every edge at vertex a shorter than the threshold.
  template <class Push>
  void push_short_edges(int a, Push&& push) {
    for (int c : cells_of(a)) {
      const int n = len_[c];
      const int* loop = &loop_[mesh_.offsets()[c]];
      for (int k = 0; k < n; ++k) {
        if (loop[k] != a) continue;
        for (int nb : {loop[(k + 1) % n], loop[(k + n - 1) % n]})
          if (length(a, nb) < threshold_) push(length(a, nb), std::min(a, nb), std::max(a, nb));
      }
    }
  }
  PolygonMesh build() const;

 private:
  std::vector<int> cells_of(int r) const {
    std::vector<int> cells;
    for (int m = r; m >= 0; m = next_member_[m])
      for (int c : mesh_.vertex_cells(m)) cells.push_back(c);
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    return cells;
  }
  bool merged_position(int a, int b, Point& out) const;
  bool loop_acceptable(const std::vector<int>& loop, int a, const Point& pa) const;

  const PolygonMesh& mesh_;
  double threshold_;
  double min_fan_area_ = 0.0;
  std::vector<Point> pos_;
  std::vector<int> loop_;
  std::vector<int> len_;
  std::vector<int> parent_, next_member_, last_member_;
  std::vector<unsigned> sides_;
};

// Where the merged vertex goes: corners never move, side vertices stay on their side.
bool CollapsibleMesh::merged_position(int a, int b, Point& out) const {
  const unsigned sa = sides_[a], sb = sides_[b], s = sa | sb;
  if (std::popcount(sa) == 2 && std::popcount(sb) == 2) return false;  // two corners
  if ((s & (kLeft | kRight)) == (kLeft | kRight) || (s & (kBottom | kTop)) == (kBottom | kTop))
    return false;  // opposite sides: the domain is thinner than the threshold
  const Rectangle& dom = mesh_.domain();
  if (std::popcount(s) == 2) {  // a corner, or one vertex on each side next to it
    out = Point((s & kLeft) ? dom.x0() : dom.x1(), (s & kBottom) ? dom.y0() : dom.y1());
    return true;
  }
  if (std::popcount(s) == 1 && sa != sb) {
    out = sa ? pos_[a] : pos_[b];
    return true;
  }
  out = 0.5 * (pos_[a] + pos_[b]);
  return true;
}

bool CollapsibleMesh::loop_acceptable(const std::vector<int>& loop, int a, const Point& pa) const {
  if (loop.size() < 3) return false;
  std::vector<Point> pts;
  pts.reserve(loop.size());
  for (int v : loop) pts.push_back(v == a ? pa : pos_[v]);
  const double area = polygon::signed_area(pts);
  if (!(area > min_fan_area_)) return false;
  if (polygon::self_intersects(pts)) return false;
  // Voronoi cells are convex; a collapse may not make a reflex corner (a vertex dragged onto a
  // side vertex would otherwise leave angles above 220 degrees next to the sides).
  for (std::size_t k = 0; k < pts.size(); ++k)
    if (polygon::orient2(pts[(k + pts.size() - 1) % pts.size()], pts[k],
                         pts[(k + 1) % pts.size()]) <
        -kConvexTolerance * (pts[(k + 1) % pts.size()] - pts[k]).squaredNorm())
      return false;
  return polygon::star_shaped_about(pts, polygon::centroid(pts, area), min_fan_area_);
}

bool CollapsibleMesh::try_collapse(int a, int b, int min_sides) {
  Point pa;
  if (!merged_position(a, b, pa)) return false;
  std::vector<int> cells = cells_of(a);
  for (int c : cells_of(b)) cells.push_back(c);
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());

  std::vector<std::vector<int>> new_loops(cells.size());
  bool is_edge = false;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const int c = cells[i];
    const int* loop = &loop_[mesh_.offsets()[c]];
    const int n = len_[c];
    int ka = -1, kb = -1;
    for (int k = 0; k < n; ++k) {
      if (loop[k] == a) ka = k;
      if (loop[k] == b) kb = k;
    }
    if (ka >= 0 && kb >= 0) {
      const int gap = (kb - ka + n) % n;
      if (gap != 1 && gap != n - 1) return false;  // would pinch the cell in two
      is_edge = true;
    }
    auto& out = new_loops[i];
    for (int k = 0; k < n; ++k) {
      const int v = loop[k] == b ? a : loop[k];
      if (!out.empty() && out.back() == v) continue;
      out.push_back(v);
    }
    while (out.size() > 1 && out.back() == out.front()) out.pop_back();
    if (static_cast<int>(out.size()) < min_sides || !loop_acceptable(out, a, pa)) return false;
  }
  if (!is_edge) return false;

  for (std::size_t i = 0; i < cells.size(); ++i) {
    const int c = cells[i];
    std::copy(new_loops[i].begin(), new_loops[i].end(), loop_.begin() + mesh_.offsets()[c]);
    len_[c] = static_cast<int>(new_loops[i].size());
  }
  pos_[a] = pa;
  sides_[a] |= sides_[b];
  parent_[b] = a;
  next_member_[last_member_[a]] = b;
  last_member_[a] = last_member_[b];
  return true;
}

PolygonMesh CollapsibleMesh::build() const {
  std::vector<std::span<const int>> loops;
  for (int c = 0; c < mesh_.num_cells(); ++c)
    loops.emplace_back(&loop_[mesh_.offsets()[c]], len_[c]);
  return compact_mesh(mesh_, pos_, loops);
}

}  // namespace

namespace {

bool acceptable_cell(const std::vector<Point>& pts) {
  const double area = polygon::signed_area(pts);
  if (!(area > 0.0) || polygon::self_intersects(pts)) return false;
  return polygon::star_shaped_about(pts, polygon::centroid(pts, area), 0.0);
}

/// Loop of the union of cells c and nb, which share exactly the edge `e`. An end vertex of the
/// shared edge that belongs to no third cell disappears (its two remaining edges are collinear
/// boundary edges, or it would hang inside the merged cell).
std::vector<int> union_loop(const PolygonMesh& mesh, int c, int nb, int e) {
  const MeshEdge& edge = mesh.edge(e);
  const auto lc = mesh.cell_vertices(c), ln = mesh.cell_vertices(nb);
  // Walk c from the end of the shared edge round to its start, then nb likewise.
  auto walk = [](std::span<const int> loop, int from, int to, std::vector<int>& out) {
    const int n = static_cast<int>(loop.size());
    int k = static_cast<int>(std::find(loop.begin(), loop.end(), from) - loop.begin());
    for (int step = 0; step < n; ++step, k = (k + 1) % n) {
      out.push_back(loop[k]);
      if (loop[k] == to) break;
    }
  };
  const int a = edge.v0, b = edge.v1;  // c or nb traverses a -> b
  std::vector<int> loop;
  const bool c_forward = edge.cell0 == c;
  walk(lc, c_forward ? b : a, c_forward ? a : b, loop);
  loop.pop_back();
  walk(ln, c_forward ? a : b, c_forward ? b : a, loop);
  loop.pop_back();
  // Drop an end vertex left between two collinear edges of the merged cell only (a corner of the
  // domain, or any bend, must stay).
  for (int v : {a, b}) {
    if (mesh.vertex_cells(v).size() != 2) continue;
    const auto it = std::find(loop.begin(), loop.end(), v);
    const std::size_t k = it - loop.begin(), n = loop.size();
    const Point& prev = mesh.vertex(loop[(k + n - 1) % n]);
    const Point& next = mesh.vertex(loop[(k + 1) % n]);
    const double scale = (next - prev).squaredNorm();
    if (std::abs(polygon::orient2(prev, mesh.vertex(v), next)) <= 1e-12 * scale) loop.erase(it);
  }
  return loop;
}

int shared_edge_count(const PolygonMesh& mesh, int c, int nb) {
  int count = 0;
  for (int k = 0; k < mesh.cell_size(c); ++k) count += mesh.neighbor(c, k) == nb;
  return count;
}

}  // namespace

PolygonMesh merge_small_cells(const PolygonMesh& mesh, int min_sides, int max_sides, int& merged) {
  merged = 0;
  std::vector<std::vector<int>> loops(mesh.num_cells());
  std::vector<char> touched(mesh.num_cells(), 0), removed(mesh.num_cells(), 0);
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto loop = mesh.cell_vertices(c);
    loops[c].assign(loop.begin(), loop.end());
  }
  for (int c = 0; c < mesh.num_cells(); ++c) {
    if (mesh.cell_size(c) >= min_sides || touched[c]) continue;
    // Best neighbour: the union with the smallest largest angle (Voronoi cells are convex;
    // keep the merged cell as close to that as the neighbours allow), then the fewest sides.
    int best = -1;
    std::vector<int> best_loop;
    double best_angle = 0.0;
    for (int k = 0; k < mesh.cell_size(c); ++k) {
      const int nb = mesh.neighbor(c, k);
      if (nb < 0 || touched[nb] || shared_edge_count(mesh, c, nb) != 1) continue;
      auto loop = union_loop(mesh, c, nb, mesh.cell_edges(c)[k]);
      if (static_cast<int>(loop.size()) > max_sides) continue;
      std::vector<Point> pts;
      for (int v : loop) pts.push_back(mesh.vertex(v));
      if (!acceptable_cell(pts)) continue;
      const double angle = polygon::max_interior_angle(pts);
      if (best >= 0 &&
          std::make_pair(angle, loop.size()) >= std::make_pair(best_angle, best_loop.size()))
        continue;
      best = nb;
      best_angle = angle;
      best_loop = std::move(loop);
    }
    if (best < 0) continue;
    loops[best] = std::move(best_loop);
    touched[best] = touched[c] = 1;
    removed[c] = 1;
    ++merged;
  }
  if (merged == 0) return mesh;
  std::vector<std::span<const int>> kept;
  for (int c = 0; c < mesh.num_cells(); ++c)
    if (!removed[c]) kept.emplace_back(loops[c]);
  return compact_mesh(mesh, mesh.vertices(), kept);
}

RegularizationResult regularize_mesh(const PolygonMesh& mesh, double threshold, int min_sides,
                                     int max_sides) {
  RegularizationResult result;
  if (!(threshold > 0.0)) {
    result.mesh = mesh;
    return result;
  }
  CollapsibleMesh work(mesh, threshold);
  using Candidate = std::tuple<double, int, int>;
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<>> queue;
  auto push = [&](double len, int a, int b) { queue.emplace(len, a, b); };
  for (int e = 0; e < mesh.num_edges(); ++e)
    if (mesh.edge_length(e) < threshold)
      push(mesh.edge_length(e), std::min(mesh.edge(e).v0, mesh.edge(e).v1),
           std::max(mesh.edge(e).v0, mesh.edge(e).v1));

  // Shortest first; an entry whose edge has changed since it was queued is re-queued with its
  // current length (lazy deletion).
  std::vector<std::pair<int, int>> refused;
  while (!queue.empty()) {
    auto [len, a, b] = queue.top();
    queue.pop();
    a = work.root(a);
    b = work.root(b);
    if (a == b) continue;
    if (a > b) std::swap(a, b);
    const double now = work.length(a, b);
    if (now >= threshold) continue;
    if (now > len) {
      push(now, a, b);
      continue;
    }
    if (work.try_collapse(a, b, 3)) {
      ++result.collapsed_edges;
      work.push_short_edges(a, push);
    } else {
      refused.emplace_back(a, b);
    }
  }
  // Cells with too many sides lose their shortest edge that can go without leaving a neighbour
  // with fewer than min_sides sides.
  for (int c = 0; c < mesh.num_cells(); ++c) {
    while (work.cell_size(c) > max_sides) {
      bool collapsed = false;
      for (auto [len, a, b] : work.edges_by_length(c))
        if ((collapsed = work.try_collapse(a, b, min_sides))) break;
      if (!collapsed) break;
      ++result.collapsed_edges;
    }
  }
  // Count refusals that still stand (an edge refused once may have vanished later).
  for (auto [a, b] : refused)
    if (work.root(a) != work.root(b) && work.length(work.root(a), work.root(b)) < threshold)
      ++result.refused_collapses;
  result.mesh = merge_small_cells(work.build(), min_sides, max_sides, result.merged_cells);
  return result;
}

}  // namespace vorodg
