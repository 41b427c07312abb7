#pragma once
// Meshes and element tables shared by the element-layer tests: one small mesh per family on
// [0,2] x [0,1] (fixed seed), built once per test program and cached.
#include <Eigen/Core>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <numbers>
#include <string>

#include "core/element/ElementTable.hpp"
#include "core/meshgen/MeshFamily.hpp"

namespace vorodg::testing {

struct Family {
  const char* name;
  MeshFamily family;
  double size;
  double perturbation;
};

inline const Family kFamilies[] = {
    {"rcp", MeshFamily::rcp, 0.1, 0.0},
    {"hex", MeshFamily::hex, 0.1, 0.0},
    {"perturbed-hex-0.3", MeshFamily::perturbed_hex, 0.1, 0.3},
    {"perturbed-hex-0.4", MeshFamily::perturbed_hex, 0.1, 0.4},
    {"tri", MeshFamily::tri, 0.1, 0.0},
    {"quad", MeshFamily::quad, 0.1, 0.0},
};

inline const PolygonMesh& mesh_of(const Family& f) {
  static std::map<std::string, PolygonMesh> cache;
  auto it = cache.find(f.name);
  if (it == cache.end()) {
    MeshSpec spec;
    spec.family = f.family;
    spec.domain = Rectangle(0.0, 0.0, 2.0, 1.0);
    spec.size = f.size;
    spec.perturbation = f.perturbation;
    spec.seed = 17;
    it = cache.emplace(f.name, generate_mesh(spec).mesh).first;
  }
  return it->second;
}

inline const ElementTable& table_of(const Family& f, int rule_points, bool correction,
                                    WeightFunctionOptions weights = {}) {
  static std::map<std::string, std::unique_ptr<ElementTable>> cache;
  const std::string key = std::string(f.name) + "/" + std::to_string(rule_points) + "/" +
                          std::to_string(correction) + "/" + std::to_string(weights.refinement) +
                          "/" + std::to_string(weights.degree);
  auto it = cache.find(key);
  if (it == cache.end()) {
    ElementOptions o;
    o.rule_points = rule_points;
    o.divergence_correction = correction;
    o.weights = weights;
    it = cache.emplace(key, std::make_unique<ElementTable>(mesh_of(f), o)).first;
  }
  return *it->second;
}

/// A generated mesh of `family` on `domain` (size = d or h of the family).
inline PolygonMesh make_mesh(MeshFamily family, const Rectangle& domain, double size,
                             std::uint64_t seed, double r = 0.3) {
  MeshSpec spec;
  spec.family = family;
  spec.domain = domain;
  spec.size = size;
  spec.seed = seed;
  spec.perturbation = r;
  return generate_mesh(spec).mesh;
}

/// A label made safe for a GoogleTest parameter name.
inline std::string test_name(std::string n) {
  for (char& ch : n)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
}

/// Length scale of a cell for relative tolerances.
inline double cell_scale(const PolygonMesh& m, int c) {
  return std::sqrt(m.cell_area(c));
}

/// Largest interior angle of cell c in degrees.
inline double largest_angle_degrees(const PolygonMesh& m, int c) {
  const auto p = m.cell_points(c);
  const int n = static_cast<int>(p.size());
  double largest = 0.0;
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d a = p[(k + n - 1) % n] - p[k], b = p[(k + 1) % n] - p[k];
    double angle = std::atan2(b.x() * a.y() - b.y() * a.x(), a.dot(b));
    if (angle < 0) angle += 2 * std::numbers::pi;
    largest = std::max(largest, angle * 180.0 / std::numbers::pi);
  }
  return largest;
}

}  // namespace vorodg::testing
