#pragma once
// The solid side of a fixed rigid plane, {x : (x - point) . n < 0}, as both plane laws (the
// exact one and the report's penalty one) see it: a point on the plane and the unit normal into
// free space.
#include <cmath>
#include <string>

#include "core/geometry/Rectangle.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {

struct HalfPlane {
  Point point = Point::Zero();
  Point normal = Point(0.0, 1.0);  // unit

  /// `normal` is normalized. Throws InputError naming `what` for a zero or non-finite normal,
  /// or a non-finite point.
  HalfPlane(const Point& p, const Point& n, const std::string& what) : point(p), normal(n) {
    const double length = n.norm();
    if (!p.allFinite() || !std::isfinite(length) || length == 0.0)
      throw InputError(what + ": expected a finite point and a nonzero finite normal, found (" +
                       std::to_string(p.x()) + ", " + std::to_string(p.y()) + ") and (" +
                       std::to_string(n.x()) + ", " + std::to_string(n.y()) + ")");
    normal /= length;
  }
  /// Signed distance from the plane, negative inside the solid.
  double gap(const Point& x) const { return (x - point).dot(normal); }
};

}  // namespace vorodg
