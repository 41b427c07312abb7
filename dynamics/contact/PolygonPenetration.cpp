#include "dynamics/contact/PolygonPenetration.hpp"

#include <algorithm>
#include <limits>

namespace vorodg {
namespace {

// A depth below this fraction of the edge's length is a point on the boundary up to round-off:
// touching, not penetrating. It also keeps the direction q - p well defined.
constexpr double kTouching = 1e-12;

struct Closest {
  int edge = -1;
  double t = 0.0;
  double distance2 = std::numeric_limits<double>::infinity();
};

/// Closest point of p on segment [a, b], as the parameter t and the squared distance.
void closest_on_edge(const Point& p, const Point& a, const Point& b, int k, Closest& best) {
  const Point e = b - a;
  const double len2 = e.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(e) / len2, 0.0, 1.0) : 0.0;
  const double d2 = (a + t * e - p).squaredNorm();
  if (d2 < best.distance2) best = {k, t, d2};  // strict: the first of equals wins
}

}  // namespace

bool PolygonPenetration::inside(const Point& p, std::span<const Point> loop) {
  bool in = false;
  const std::size_t n = loop.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point& a = loop[i];
    const Point& b = loop[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

std::optional<Penetration> PolygonPenetration::of_point(const Point& p, std::span<const Point> b,
                                                        std::span<const char> exits) {
  if (b.size() < 3 || !inside(p, b)) return std::nullopt;
  const int n = static_cast<int>(b.size());
  Closest best;
  for (int k = 0; k < n; ++k)
    if (exits.empty() || exits[k]) closest_on_edge(p, b[k], b[(k + 1) % n], k, best);
  if (best.edge < 0) return std::nullopt;
  const Point& a = b[best.edge];
  const Point e = b[(best.edge + 1) % n] - a;
  const Point q = a + best.t * e;
  const double depth = (q - p).norm();
  if (depth <= kTouching * e.norm()) return std::nullopt;
  Penetration out;
  out.edge = best.edge;
  out.t = best.t;
  out.depth = depth;
  out.normal = (q - p) / depth;
  return out;
}

void PolygonPenetration::vertices_inside(std::span<const Point> a, std::span<const Point> b,
                                         std::span<const char> exits_b,
                                         std::vector<Penetration>& out) {
  for (std::size_t i = 0; i < a.size(); ++i)
    if (auto pen = of_point(a[i], b, exits_b)) {
      pen->vertex = static_cast<int>(i);
      out.push_back(*pen);
    }
}

}  // namespace vorodg
