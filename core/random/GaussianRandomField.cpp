#include "core/random/GaussianRandomField.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "core/util/Errors.hpp"

namespace vorodg {

GaussianRandomField::GaussianRandomField(const CirculantEmbedding& embedding, std::uint64_t seed)
    : domain_(embedding.domain()),
      spacing_(embedding.spacing()),
      nx_(embedding.nodes_x()),
      ny_(embedding.nodes_y()),
      values_(embedding.sample(seed)) {}

GaussianRandomField::GaussianRandomField(const Rectangle& domain, const FieldCovariance& covariance,
                                         std::uint64_t seed, double spacing)
    : GaussianRandomField(CirculantEmbedding(domain, covariance, spacing), seed) {}

double GaussianRandomField::value(const Point& x) const {
  const double slack = 1e-9 * domain_.scale();
  if (!(x.x() >= domain_.x0() - slack && x.x() <= domain_.x1() + slack &&
        x.y() >= domain_.y0() - slack && x.y() <= domain_.y1() + slack))
    throw InputError("random field: the point (" + std::to_string(x.x()) + ", " +
                     std::to_string(x.y()) + ") lies outside the field's domain");
  const double sx = std::clamp((x.x() - domain_.x0()) / spacing_, 0.0, double(nx_ - 1));
  const double sy = std::clamp((x.y() - domain_.y0()) / spacing_, 0.0, double(ny_ - 1));
  const int i = std::min(static_cast<int>(sx), nx_ - 2),
            j = std::min(static_cast<int>(sy), ny_ - 2);
  const double tx = sx - i, ty = sy - j;
  return (1.0 - tx) * ((1.0 - ty) * node(i, j) + ty * node(i, j + 1)) +
         tx * ((1.0 - ty) * node(i + 1, j) + ty * node(i + 1, j + 1));
}

double GaussianRandomField::mean_over(std::span<const Point> polygon,
                                      const std::function<double(double)>& of) const {
  if (polygon.size() < 3)
    throw InputError("random field: a polygon of " + std::to_string(polygon.size()) +
                     " vertices: expected at least 3");
  Point centre = Point::Zero();
  for (const Point& p : polygon) centre += p;
  centre /= static_cast<double>(polygon.size());
  // Each fan triangle is split into 4^k by its edges' midpoints until its pieces are no wider
  // than two grid spacings, so the rule sees the field's variation inside a large cell.
  double integral = 0.0, area = 0.0;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const Point& a = polygon[k];
    const Point& b = polygon[(k + 1) % polygon.size()];
    const double width = std::max({(a - centre).norm(), (b - centre).norm(), (b - a).norm()});
    const int levels =
        std::clamp(static_cast<int>(std::ceil(std::log2(width / (2.0 * spacing_)))), 0, 6);
    std::vector<std::array<Point, 3>> pieces{{centre, a, b}};
    for (int level = 0; level < levels; ++level) {
      std::vector<std::array<Point, 3>> finer;
      finer.reserve(4 * pieces.size());
      for (const auto& [p, q, r] : pieces) {
        const Point pq = 0.5 * (p + q), qr = 0.5 * (q + r), rp = 0.5 * (r + p);
        finer.push_back({p, pq, rp});
        finer.push_back({pq, q, qr});
        finer.push_back({rp, qr, r});
        finer.push_back({pq, qr, rp});
      }
      pieces = std::move(finer);
    }
    const auto at = [&](const Point& x) { return of ? of(value(x)) : value(x); };
    for (const auto& [p, q, r] : pieces) {
      const double piece = 0.5 * ((q - p).x() * (r - p).y() - (q - p).y() * (r - p).x());
      integral += piece * (at(0.5 * (p + q)) + at(0.5 * (q + r)) + at(0.5 * (r + p))) / 3.0;
      area += piece;
    }
  }
  if (!(std::abs(area) > 0.0)) throw InputError("random field: a polygon of zero area has no mean");
  return integral / area;
}

}  // namespace vorodg
