#include "core/geometry/Polygon.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vorodg::polygon {

double signed_area(std::span<const Point> loop) {
  const std::size_t n = loop.size();
  if (n < 3) return 0.0;
  const Point& o = loop[0];
  double twice = 0.0;
  for (std::size_t i = 1; i + 1 < n; ++i) twice += orient2(o, loop[i], loop[i + 1]);
  return 0.5 * twice;
}

Point centroid(std::span<const Point> loop, double area) {
  const std::size_t n = loop.size();
  const Point& o = loop[0];
  Point sum = Point::Zero();
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double a2 = orient2(o, loop[i], loop[i + 1]);
    sum += a2 * ((loop[i] - o) + (loop[i + 1] - o)) / 3.0;
  }
  return o + sum / (2.0 * area);
}

bool segments_intersect(const Point& p1, const Point& p2, const Point& q1, const Point& q2) {
  const double d1 = orient2(q1, q2, p1);
  const double d2 = orient2(q1, q2, p2);
  const double d3 = orient2(p1, p2, q1);
  const double d4 = orient2(p1, p2, q2);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;
  auto on_segment = [](const Point& a, const Point& b, const Point& p) {
    return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
           std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y());
  };
  if (d1 == 0 && on_segment(q1, q2, p1)) return true;
  if (d2 == 0 && on_segment(q1, q2, p2)) return true;
  if (d3 == 0 && on_segment(p1, p2, q1)) return true;
  if (d4 == 0 && on_segment(p1, p2, q2)) return true;
  return false;
}

bool self_intersects(std::span<const Point> loop) {
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      if (loop[i] == loop[j]) return true;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through the closing edge
      if (segments_intersect(loop[i], loop[(i + 1) % n], loop[j], loop[(j + 1) % n])) return true;
    }
  }
  return false;
}

bool star_shaped_about(std::span<const Point> loop, const Point& c, double min_area) {
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i)
    if (0.5 * orient2(c, loop[i], loop[(i + 1) % n]) <= min_area) return false;
  return true;
}

double interior_angle(std::span<const Point> loop, std::size_t i) {
  const std::size_t n = loop.size();
  const Point& here = loop[i];
  const Point a = loop[(i + 1) % n] - here;
  const Point b = loop[(i + n - 1) % n] - here;
  // Angle swept counter-clockwise from (next - here) to (prev - here): the interior angle
  // of a counter-clockwise loop.
  double angle = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
  if (angle < 0) angle += 2.0 * std::numbers::pi;
  return angle;
}

double min_interior_angle(std::span<const Point> loop) {
  double smallest = 2.0 * std::numbers::pi;
  for (std::size_t i = 0; i < loop.size(); ++i)
    smallest = std::min(smallest, interior_angle(loop, i));
  return smallest;
}

double max_interior_angle(std::span<const Point> loop) {
  double largest = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i)
    largest = std::max(largest, interior_angle(loop, i));
  return largest;
}

double distance_to_segment(const Point& p, const Point& a, const Point& b) {
  const Point ab = b - a;
  const double len2 = ab.squaredNorm();
  double t = len2 > 0 ? (p - a).dot(ab) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return (a + t * ab - p).norm();
}

}  // namespace vorodg::polygon
