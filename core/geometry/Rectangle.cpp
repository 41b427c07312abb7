#include "core/geometry/Rectangle.hpp"

#include <charconv>
#include <cmath>
#include <ostream>
#include <sstream>
#include <vector>

#include "core/util/Errors.hpp"

namespace vorodg {

std::string_view side_name(Side s) {
  switch (s) {
    case Side::left: return "left";
    case Side::right: return "right";
    case Side::bottom: return "bottom";
    case Side::top: return "top";
    default: return "none";
  }
}

std::ostream& operator<<(std::ostream& os, Side s) {
  return os << side_name(s);
}

Rectangle::Rectangle(double x0, double y0, double x1, double y1) : lo_(x0, y0), hi_(x1, y1) {
  const bool finite =
      std::isfinite(x0) && std::isfinite(y0) && std::isfinite(x1) && std::isfinite(y1);
  if (!finite || !(x0 < x1) || !(y0 < y1))
    throw InputError("domain " + to_string() + ": expected finite x0 < x1 and y0 < y1");
}

Rectangle Rectangle::parse(const std::string& text) {
  std::vector<double> v;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t comma = std::min(text.find(',', pos), text.size());
    const char* first = text.data() + pos;
    const char* last = text.data() + comma;
    while (first < last && *first == ' ') ++first;
    double x = 0.0;
    auto [ptr, ec] = std::from_chars(first, last, x);
    if (ec != std::errc() || ptr != last)
      throw InputError("domain '" + text + "': expected four numbers x0,y0,x1,y1");
    v.push_back(x);
    pos = comma + 1;
  }
  if (v.size() != 4) throw InputError("domain '" + text + "': expected four numbers x0,y0,x1,y1");
  return Rectangle(v[0], v[1], v[2], v[3]);
}

double Rectangle::side_coordinate(Side s) const {
  switch (s) {
    case Side::left: return lo_.x();
    case Side::right: return hi_.x();
    case Side::bottom: return lo_.y();
    case Side::top: return hi_.y();
    default: return std::nan("");
  }
}

double Rectangle::distance_to_side(const Point& p, Side s) const {
  const bool vertical = (s == Side::left || s == Side::right);
  return std::abs((vertical ? p.x() : p.y()) - side_coordinate(s));
}

std::array<bool, 4> Rectangle::sides_near(const Point& p, double tol) const {
  std::array<bool, 4> near{};
  for (int k = 0; k < 4; ++k) near[k] = distance_to_side(p, static_cast<Side>(k)) <= tol;
  return near;
}

Side Rectangle::common_side(const Point& a, const Point& b, double tol) const {
  const auto na = sides_near(a, tol);
  const auto nb = sides_near(b, tol);
  for (int k = 0; k < 4; ++k)
    if (na[k] && nb[k]) return static_cast<Side>(k);
  return Side::none;
}

bool Rectangle::contains(const Point& p, double tol) const {
  return p.x() >= lo_.x() - tol && p.x() <= hi_.x() + tol && p.y() >= lo_.y() - tol &&
         p.y() <= hi_.y() + tol;
}

Point Rectangle::snap(const Point& p, double tol) const {
  Point q = p;
  if (std::abs(q.x() - lo_.x()) <= tol) q.x() = lo_.x();
  if (std::abs(q.x() - hi_.x()) <= tol) q.x() = hi_.x();
  if (std::abs(q.y() - lo_.y()) <= tol) q.y() = lo_.y();
  if (std::abs(q.y() - hi_.y()) <= tol) q.y() = hi_.y();
  return q;
}

std::string Rectangle::to_string() const {
  std::ostringstream os;
  os.precision(17);
  os << lo_.x() << ',' << lo_.y() << ',' << hi_.x() << ',' << hi_.y();
  return os.str();
}

}  // namespace vorodg
