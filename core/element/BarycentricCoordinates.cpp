#include "core/element/BarycentricCoordinates.hpp"

#include <cmath>
#include <vector>

namespace vorodg {
namespace {

/// A number with its gradient with respect to the evaluation point: forward-mode
/// differentiation, so the coordinates' gradients come from the same formulas as their values.
struct Dual {
  double v = 0.0;
  Eigen::Vector2d d = Eigen::Vector2d::Zero();
};

Dual operator+(const Dual& a, const Dual& b) {
  return {a.v + b.v, a.d + b.d};
}
Dual operator-(const Dual& a, const Dual& b) {
  return {a.v - b.v, a.d - b.d};
}
Dual operator*(const Dual& a, const Dual& b) {
  return {a.v * b.v, a.d * b.v + a.v * b.d};
}
Dual operator*(double s, const Dual& a) {
  return {s * a.v, s * a.d};
}
Dual operator/(const Dual& a, const Dual& b) {
  return {a.v / b.v, (a.d * b.v - a.v * b.d) / (b.v * b.v)};
}
Dual sqrt(const Dual& a) {
  const double r = std::sqrt(a.v);
  return {r, a.d / (2.0 * r)};
}

/// A node seen from the evaluation point: d = v - x, whose gradient with respect to x is -I.
struct Arm {
  Dual x, y;
};

Arm arm(const Eigen::Vector2d& node, const Eigen::Vector2d& at) {
  return {{node.x() - at.x(), Eigen::Vector2d(-1.0, 0.0)},
          {node.y() - at.y(), Eigen::Vector2d(0.0, -1.0)}};
}

Dual cross(const Arm& a, const Arm& b) {
  return a.x * b.y - a.y * b.x;
}
Dual dot(const Arm& a, const Arm& b) {
  return a.x * b.x + a.y * b.y;
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

/// Wachspress's weights in product form, w_i = C_i prod_{j != i-1, i} A_j(x), with A_j the area
/// of (x, v_j, v_j+1) and C_i that of (v_i-1, v_i, v_i+1): the usual C_i / (A_i-1 A_i) times the
/// product of all A_j, which divides by nothing and so stays accurate next to the edges.
void wachspress_weights(std::span<const Eigen::Vector2d> nodes, const Eigen::Vector2d& x,
                        std::vector<Dual>& w) {
  const int n = static_cast<int>(nodes.size());
  std::vector<Arm> arms(n);
  for (int k = 0; k < n; ++k) arms[k] = arm(nodes[k], x);
  std::vector<Dual> area(n);
  for (int j = 0; j < n; ++j) area[j] = 0.5 * cross(arms[j], arms[(j + 1) % n]);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d& prev = nodes[(i + n - 1) % n];
    const Eigen::Vector2d& next = nodes[(i + 1) % n];
    Dual product{0.5 * cross(nodes[i] - prev, next - prev), Eigen::Vector2d::Zero()};
    for (int j = 0; j < n; ++j)
      if (j != i && j != (i + n - 1) % n) product = product * area[j];
    w[i] = product;
  }
}

/// Floater's mean value weights, w_i = (tan(a_i-1 / 2) + tan(a_i / 2)) / r_i, with a_j the
/// signed angle at x between the arms d_j, d_j+1 to v_j and v_j+1. tan(a/2) has two forms,
/// sin a / (1 + cos a) = c / (r r' + D) and (1 - cos a) / sin a = (r r' - D) / c (c the arms'
/// cross product, D their dot product): each is taken where its subtraction cannot cancel, the
/// first for a < 90 degrees (also a = 0, a non-convex cell's edge seen end-on), the second
/// beyond, where next to an edge (a -> 180 degrees) the large weights of the edge's two
/// vertices share the factor 1 / c and their ratio stays exact.
void mean_value_weights(std::span<const Eigen::Vector2d> nodes, const Eigen::Vector2d& x,
                        std::vector<Dual>& w) {
  const int n = static_cast<int>(nodes.size());
  std::vector<Arm> arms(n);
  std::vector<Dual> length(n), half_tan(n);
  for (int k = 0; k < n; ++k) {
    arms[k] = arm(nodes[k], x);
    length[k] = sqrt(dot(arms[k], arms[k]));
  }
  for (int j = 0; j < n; ++j) {
    const int next = (j + 1) % n;
    const Dual c = cross(arms[j], arms[next]), D = dot(arms[j], arms[next]);
    const Dual rr = length[j] * length[next];
    half_tan[j] = D.v >= 0.0 ? c / (rr + D) : (rr - D) / c;
  }
  for (int i = 0; i < n; ++i) w[i] = (half_tan[(i + n - 1) % n] + half_tan[i]) / length[i];
}

}  // namespace

void barycentric_coordinates(BarycentricKind kind, std::span<const Eigen::Vector2d> nodes,
                             const Eigen::Vector2d& x, double* psi, Eigen::Vector2d* grad) {
  const int n = static_cast<int>(nodes.size());
  thread_local std::vector<Dual> w;
  w.resize(n);
  if (kind == BarycentricKind::wachspress)
    wachspress_weights(nodes, x, w);
  else
    mean_value_weights(nodes, x, w);
  Dual sum;
  for (int i = 0; i < n; ++i) sum = sum + w[i];
  for (int i = 0; i < n; ++i) {
    const Dual phi = w[i] / sum;  // normalized: the partition of unity
    psi[i] = phi.v;
    grad[i] = phi.d;
  }
}

int first_non_convex_corner(std::span<const Eigen::Vector2d> nodes) {
  const int n = static_cast<int>(nodes.size());
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d& prev = nodes[(k + n - 1) % n];
    const Eigen::Vector2d& next = nodes[(k + 1) % n];
    const Eigen::Vector2d in = nodes[k] - prev, out = next - nodes[k];
    // Relative to the edges' lengths: a corner straight to round-off counts as straight.
    if (!(cross(in, out) > 1e-12 * in.norm() * out.norm())) return k;
  }
  return -1;
}

}  // namespace vorodg
