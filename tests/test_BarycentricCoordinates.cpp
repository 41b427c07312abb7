// Generalized barycentric coordinates (core/element/BarycentricCoordinates):
// 1. Wachspress and mean value values agree with CGAL's Barycentric_coordinates_2 at random
//    points of convex polygons (and mean value on a non-convex star-shaped one) to 1e-12.
// 2. They are a partition of unity with linear precision, and so are their gradients:
//    sum psi = 1, sum psi v = x, sum grad psi = 0, sum v (x) grad psi = I (to 1e-12).
// 3. The gradients match central differences of the values (relative 1e-6).
// 4. Next to an edge the coordinates are the linear interpolation between its two vertices, and
//    their gradients are finite and converge to the limit from inside.
// 5. first_non_convex_corner finds a reflex or straight corner, and none on a convex polygon.
#include <gtest/gtest.h>

#include <CGAL/Barycentric_coordinates_2/Mean_value_coordinates_2.h>
#include <CGAL/Barycentric_coordinates_2/Wachspress_coordinates_2.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/element/BarycentricCoordinates.hpp"

namespace vorodg {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Polygon = std::vector<Eigen::Vector2d>;

/// A convex n-gon: points at increasing random angles on an ellipse.
Polygon convex_polygon(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  Polygon p;
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * M_PI * (k + 0.5 + jitter(rng)) / n;
    p.emplace_back(1.5 + 2.0 * std::cos(a), -0.7 + std::sin(a));
  }
  return p;
}

/// A non-convex polygon star-shaped about the origin: an arrow head.
Polygon arrow() {
  return {{-1, -1}, {0, -0.3}, {1, -1}, {0, 1}};
}

/// A random point of the polygon's kernel: a convex combination pulled towards `centre`.
Eigen::Vector2d inside(const Polygon& p, const Eigen::Vector2d& centre, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int k = std::uniform_int_distribution<int>(0, static_cast<int>(p.size()) - 1)(rng);
  const Eigen::Vector2d edge_point = p[k] + u(rng) * (p[(k + 1) % p.size()] - p[k]);
  return centre + 0.95 * u(rng) * (edge_point - centre);
}

std::vector<double> cgal_coordinates(BarycentricKind kind, const Polygon& p,
                                     const Eigen::Vector2d& x) {
  std::vector<Kernel::Point_2> polygon;
  for (const auto& v : p) polygon.emplace_back(v.x(), v.y());
  std::vector<double> out;
  const Kernel::Point_2 q(x.x(), x.y());
  if (kind == BarycentricKind::wachspress)
    CGAL::Barycentric_coordinates::wachspress_coordinates_2(polygon, q, std::back_inserter(out));
  else
    CGAL::Barycentric_coordinates::mean_value_coordinates_2(polygon, q, std::back_inserter(out));
  return out;
}

struct Values {
  std::vector<double> psi;
  std::vector<Eigen::Vector2d> grad;
};

Values coordinates(BarycentricKind kind, const Polygon& p, const Eigen::Vector2d& x) {
  Values v{std::vector<double>(p.size()), std::vector<Eigen::Vector2d>(p.size())};
  barycentric_coordinates(kind, p, x, v.psi.data(), v.grad.data());
  return v;
}

class Coordinates : public ::testing::TestWithParam<BarycentricKind> {};

TEST_P(Coordinates, AgreeWithCgal) {
  std::mt19937 rng(11);
  std::vector<Polygon> polygons;
  for (int n : {3, 4, 5, 6, 7, 9}) polygons.push_back(convex_polygon(n, rng));
  if (GetParam() == BarycentricKind::mean_value) polygons.push_back(arrow());
  for (const Polygon& p : polygons) {
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (const auto& v : p) centre += v / static_cast<double>(p.size());
    if (p.size() == 4 && p[3] == Eigen::Vector2d(0, 1)) centre.setZero();  // the arrow's kernel
    for (int trial = 0; trial < 50; ++trial) {
      const Eigen::Vector2d x = inside(p, centre, rng);
      const Values ours = coordinates(GetParam(), p, x);
      const std::vector<double> theirs = cgal_coordinates(GetParam(), p, x);
      ASSERT_EQ(theirs.size(), p.size());
      for (std::size_t k = 0; k < p.size(); ++k)
        EXPECT_NEAR(ours.psi[k], theirs[k], 1e-12) << "n " << p.size() << " vertex " << k;
    }
  }
}

TEST_P(Coordinates, PartitionOfUnityAndLinearPrecision) {
  std::mt19937 rng(12);
  for (int n : {3, 5, 8}) {
    const Polygon p = convex_polygon(n, rng);
    for (int trial = 0; trial < 20; ++trial) {
      const Eigen::Vector2d x = inside(p, Eigen::Vector2d(1.5, -0.7), rng);
      const Values v = coordinates(GetParam(), p, x);
      double sum = 0.0;
      Eigen::Vector2d reproduced = Eigen::Vector2d::Zero(), grad_sum = Eigen::Vector2d::Zero();
      Eigen::Matrix2d identity = Eigen::Matrix2d::Zero();
      for (int k = 0; k < n; ++k) {
        sum += v.psi[k];
        reproduced += v.psi[k] * p[k];
        grad_sum += v.grad[k];
        identity += p[k] * v.grad[k].transpose();
      }
      EXPECT_NEAR(sum, 1.0, 1e-12);
      EXPECT_LT((reproduced - x).norm(), 1e-12);
      EXPECT_LT(grad_sum.norm(), 1e-11);
      EXPECT_LT((identity - Eigen::Matrix2d::Identity()).norm(), 1e-11);
    }
  }
}

TEST_P(Coordinates, GradientsMatchDifferences) {
  std::mt19937 rng(13);
  const Polygon p = convex_polygon(6, rng);
  const double h = 1e-6;
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Vector2d x = inside(p, Eigen::Vector2d(1.5, -0.7), rng);
    const Values v = coordinates(GetParam(), p, x);
    for (int d = 0; d < 2; ++d) {
      const Eigen::Vector2d step = h * Eigen::Vector2d::Unit(d);
      const Values plus = coordinates(GetParam(), p, x + step);
      const Values minus = coordinates(GetParam(), p, x - step);
      for (std::size_t k = 0; k < p.size(); ++k) {
        const double difference = (plus.psi[k] - minus.psi[k]) / (2 * h);
        EXPECT_NEAR(v.grad[k][d], difference, 1e-6 * (1.0 + std::abs(difference)));
      }
    }
  }
}

TEST_P(Coordinates, LinearOnTheEdges) {
  std::mt19937 rng(14);
  const Polygon p = convex_polygon(6, rng);
  const Eigen::Vector2d centre(1.5, -0.7);
  for (std::size_t k = 0; k < p.size(); ++k) {
    const std::size_t next = (k + 1) % p.size();
    const double t = 0.3;
    const Eigen::Vector2d on_edge = (1 - t) * p[k] + t * p[next];
    const Eigen::Vector2d x = on_edge + 1e-10 * (centre - on_edge);
    const Values v = coordinates(GetParam(), p, x);
    // The gradient there (what DG's interface tractions take, ElementTable::evaluate) is the
    // smooth limit from inside: finite, and the same as a little further in.
    const Values further = coordinates(GetParam(), p, on_edge + 1e-6 * (centre - on_edge));
    for (std::size_t j = 0; j < p.size(); ++j) {
      const double expected = j == k ? 1 - t : j == next ? t : 0.0;
      EXPECT_NEAR(v.psi[j], expected, 1e-8) << "edge " << k << " vertex " << j;
      EXPECT_TRUE(v.grad[j].allFinite());
      EXPECT_LT((v.grad[j] - further.grad[j]).norm(), 1e-4 * (1.0 + further.grad[j].norm()))
          << "edge " << k << " vertex " << j;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Kinds, Coordinates,
                         ::testing::Values(BarycentricKind::wachspress,
                                           BarycentricKind::mean_value),
                         [](const auto& info) {
                           return info.param == BarycentricKind::wachspress ? "wachspress"
                                                                            : "mean_value";
                         });

TEST(Convexity, FindsReflexAndStraightCorners) {
  const Polygon square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_EQ(first_non_convex_corner(square), -1);
  const Polygon straight = {{0, 0}, {0.5, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_EQ(first_non_convex_corner(straight), 1);
  EXPECT_EQ(first_non_convex_corner(arrow()), 1);
}

}  // namespace
}  // namespace vorodg
