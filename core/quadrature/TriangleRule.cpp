#include "core/quadrature/TriangleRule.hpp"

#include <cmath>
#include <string>

#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

/// The three permutations of barycentric point (a, b, b).
void add_orbit3(TriangleRule& rule, double a, double w) {
  const double b = 0.5 * (1.0 - a);
  rule.bary.emplace_back(a, b, b);
  rule.bary.emplace_back(b, a, b);
  rule.bary.emplace_back(b, b, a);
  rule.weights.insert(rule.weights.end(), {w, w, w});
}

TriangleRule make_rule(int points) {
  TriangleRule rule;
  switch (points) {
    case 1:
      rule.degree = 1;
      rule.bary.emplace_back(1.0 / 3, 1.0 / 3, 1.0 / 3);
      rule.weights.push_back(1.0);
      break;
    case 3:  // Strang-Fix interior rule
      rule.degree = 2;
      add_orbit3(rule, 2.0 / 3, 1.0 / 3);
      break;
    case 6:  // Dunavant, degree 4
      rule.degree = 4;
      add_orbit3(rule, 0.108103018168070, 0.223381589678011);
      add_orbit3(rule, 0.816847572980459, 0.109951743655322);
      break;
    case 7:  // Dunavant, degree 5
      rule.degree = 5;
      rule.bary.emplace_back(1.0 / 3, 1.0 / 3, 1.0 / 3);
      rule.weights.push_back(0.225);
      add_orbit3(rule, 0.059715871789770, 0.132394152788506);
      add_orbit3(rule, 0.797426985353087, 0.125939180544827);
      break;
    default:
      throw InputError("triangle rule with " + std::to_string(points) +
                       " points: expected 1, 3, 6 or 7");
  }
  return rule;
}

}  // namespace

const TriangleRule& triangle_rule(int points) {
  static const TriangleRule rules[] = {make_rule(1), make_rule(3), make_rule(6), make_rule(7)};
  switch (points) {
    case 1: return rules[0];
    case 3: return rules[1];
    case 6: return rules[2];
    case 7: return rules[3];
    default: return make_rule(points), rules[0];  // make_rule throws
  }
}

const SegmentRule& gauss2_segment() {
  static const SegmentRule rule{{0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)},
                                {0.5, 0.5}};
  return rule;
}

}  // namespace vorodg
