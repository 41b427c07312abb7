#pragma once
// Per-cell variation of the material (the report's Figure 16): each cell's Young's modulus and
// strength are the scene's times factors drawn uniformly from [1 - x, 1 + x], independently, from
// a seed. Each cell draws from its own stream (derive_seed(seed, cell)), so the factors do not
// depend on the order anything runs in. An edge's strength factor is the mean of its two cells'.
//
// Or the factors follow a random field in space (from_field, docs/statistics.md): each cell's
// factor is the mean over its polygon of the field mapped to its marginal, so a coarse cell's
// factor is the mean of what the fine cells inside it see, and realization i is the same material
// on every mesh level. With the uniform marginal the stiffness and the strength follow two
// independent fields of the same law; with the Weibull marginal (a strength law) only the
// strength varies.
//
// What the factors scale is the caller's: the explicit path scales a cell's stiffness and
// stresses and an edge's criterion (cohesion, cutoff) and cohesive strength; the quasi-static
// path scales the strength only (docs/statistics.md, "The field in the quasi-static kind").
#include <cstdint>
#include <vector>

#include "core/mesh/PolygonMesh.hpp"
#include "core/random/MaterialField.hpp"

namespace vorodg {

struct MaterialVariation {
  std::vector<double> stiffness;  // per cell; empty: uniform material
  std::vector<double> strength;   // per cell; empty: uniform material

  /// Factors uniform in [1 - amount, 1 + amount]; amount = 0 gives the uniform material (empty).
  /// Throws InputError unless 0 <= amount < 1.
  static MaterialVariation uniform(int cells, double amount, std::uint64_t seed);
  /// Realization `realization` of `field` over the mesh's domain, as cell means.
  static MaterialVariation from_field(const PolygonMesh& mesh, const MaterialField& field,
                                      int realization);
  bool empty() const { return stiffness.empty(); }
  /// Per mesh edge, the mean of its cells' strength factors (its one cell on the boundary); empty
  /// for the uniform material.
  std::vector<double> edge_strength(const PolygonMesh& mesh) const;
};

}  // namespace vorodg
