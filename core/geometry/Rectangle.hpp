#pragma once
// The rectangular domain [x0, x1] x [y0, y1] every verification problem lives on, and the
// geometric tagging of its four sides.
#include <Eigen/Core>
#include <array>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>

namespace vorodg {

using Point = Eigen::Vector2d;

/// Sides of the rectangle, in the order their tags are numbered in files. `none` marks an
/// interior edge or a boundary edge that lies on no side (a hole: a mesh defect).
enum class Side : int { none = -1, left = 0, right = 1, bottom = 2, top = 3 };

std::string_view side_name(Side s);
/// Writes the side's name (readable test and log output).
std::ostream& operator<<(std::ostream& os, Side s);

class Rectangle {
 public:
  Rectangle() = default;
  /// Throws InputError unless x0 < x1 and y0 < y1 and all are finite.
  Rectangle(double x0, double y0, double x1, double y1);
  /// Parses "x0,y0,x1,y1"; throws InputError naming the text on failure.
  static Rectangle parse(const std::string& text);

  double x0() const { return lo_.x(); }
  double y0() const { return lo_.y(); }
  double x1() const { return hi_.x(); }
  double y1() const { return hi_.y(); }
  const Point& lo() const { return lo_; }
  const Point& hi() const { return hi_; }
  double width() const { return hi_.x() - lo_.x(); }
  double height() const { return hi_.y() - lo_.y(); }
  double area() const { return width() * height(); }
  /// Length scale for relative tolerances: the larger side.
  double scale() const { return std::max(width(), height()); }

  /// Coordinate of a side's line (x for left/right, y for bottom/top).
  double side_coordinate(Side s) const;
  /// Distance from p to the line of side s.
  double distance_to_side(const Point& p, Side s) const;
  /// Sides whose line passes within `tol` of p (0, 1 or 2 of them; 2 at a corner).
  std::array<bool, 4> sides_near(const Point& p, double tol) const;
  /// The side shared by both points (within tol), or Side::none.
  Side common_side(const Point& a, const Point& b, double tol) const;
  /// True if p lies inside the rectangle enlarged by tol.
  bool contains(const Point& p, double tol) const;
  /// Moves p exactly onto every side line within tol (corner points land on the corner).
  Point snap(const Point& p, double tol) const;

  std::string to_string() const;

 private:
  Point lo_{0.0, 0.0};
  Point hi_{1.0, 1.0};
};

}  // namespace vorodg
