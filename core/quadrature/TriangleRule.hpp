#pragma once
// Quadrature on triangles (barycentric points, weights summing to 1) and on segments. The fan
// rules of the element layer use 1, 3 or 6 points; error integration uses the 7-point rule.
#include <Eigen/Core>
#include <array>
#include <vector>

namespace vorodg {

struct TriangleRule {
  int degree = 0;                     // polynomials up to this degree are exact
  std::vector<Eigen::Vector3d> bary;  // barycentric coordinates of the points
  std::vector<double> weights;        // fractions of the triangle's area, sum 1
  int size() const { return static_cast<int>(weights.size()); }
};

/// Symmetric interior rules with 1 (degree 1), 3 (degree 2), 6 (degree 4) or 7 (degree 5)
/// points. Throws InputError for any other count.
const TriangleRule& triangle_rule(int points);

/// The point counts a fan triangle's rule may have (the element layer's `rule` option).
inline constexpr std::array<int, 3> kFanRulePoints = {1, 3, 6};

/// Two-point Gauss rule on [0, 1]: exact for cubics (and so for products of the edge-linear
/// fields the interface terms integrate).
struct SegmentRule {
  std::array<double, 2> t;
  std::array<double, 2> weights;  // sum 1
};
const SegmentRule& gauss2_segment();

}  // namespace vorodg
