#pragma once
// Scenes for the contact tests: two rcp bodies in one mesh (side by side in the reference
// configuration, no shared vertex), and current positions that rotate and shift the second onto
// the first and jiggle every vertex, so that many cells of the two overlap. Fixed seeds.
#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Random.hpp"

namespace vorodg::testing {

struct TwoBodies {
  PolygonMesh mesh;
  int first_body_cells = 0;  // cells [0, first_body_cells) are the first body
  std::vector<Point> x;      // current position per (cell, vertex) pair
};

inline PolygonMesh rcp_unit_square(double d, std::uint64_t seed) {
  MeshSpec spec;
  spec.family = MeshFamily::rcp;
  spec.domain = Rectangle(0.0, 0.0, 1.0, 1.0);
  spec.size = d;
  spec.seed = seed;
  return generate_mesh(spec).mesh;
}

/// Body 1 on [0,1]^2, body 2 (another seed) on [2,3] x [0,1] in the reference mesh. In the
/// current positions body 2 is turned by `angle` about its centre and moved so that its centre
/// sits at `centre`; every vertex moves by at most `jiggle` x d (the same for all its pairs).
inline TwoBodies two_bodies(double d, std::uint64_t seed, const Point& centre, double angle,
                            double jiggle) {
  const PolygonMesh a = rcp_unit_square(d, derive_seed(seed, 0));
  const PolygonMesh b = rcp_unit_square(d, derive_seed(seed, 1));
  std::vector<Point> vertices = a.vertices();
  for (const Point& v : b.vertices()) vertices.push_back(v + Point(2.0, 0.0));
  std::vector<int> offsets = a.offsets();
  for (std::size_t c = 1; c < b.offsets().size(); ++c)
    offsets.push_back(a.offsets().back() + b.offsets()[c]);
  std::vector<int> loops = a.cell_vertex_list();
  for (int v : b.cell_vertex_list()) loops.push_back(v + a.num_vertices());
  TwoBodies out{
      PolygonMesh(Rectangle(0.0, 0.0, 3.0, 1.0), vertices, offsets, loops), a.num_cells(), {}};
  Random random(derive_seed(seed, 2));
  std::vector<Point> current(vertices.size());
  const Eigen::Rotation2Dd turn(angle);
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    const double r = jiggle * d * std::sqrt(random.uniform());
    const double phi = 2.0 * std::numbers::pi * random.uniform();
    current[v] = vertices[v] + r * Point(std::cos(phi), std::sin(phi));
    if (static_cast<int>(v) >= a.num_vertices())
      current[v] = centre + turn * (current[v] - Point(2.5, 0.5));
  }
  for (int v : out.mesh.cell_vertex_list()) out.x.push_back(current[v]);
  return out;
}

}  // namespace vorodg::testing
