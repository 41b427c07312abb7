#pragma once
// A random material field as a scene gives it: the Gaussian field's correlation, the marginal its
// factor follows, the grid spacing and the seed. Realization i of a study draws its field from
// derive_seed(seed, i), and only from that: not from the mesh's seed, so every mesh level's
// realization i sees the same material (the coupling the statistical report's E|D|^r and
// Pr(|D| > eps) need). What the factors scale (stiffness, strength) is the caller's.
#include <cstdint>

#include "core/random/FieldCovariance.hpp"
#include "core/random/FieldMarginal.hpp"

namespace vorodg {

struct MaterialField {
  bool enabled = false;
  FieldCovariance covariance;
  FieldMarginal marginal;
  double spacing = 0.0;  // of the sampling grid; 0: covariance.length / 8
  std::uint64_t seed = 1;

  /// The seed of realization `realization`'s field number `which` (independent fields for the
  /// stiffness and the strength).
  std::uint64_t field_seed(int realization, int which) const;
};

}  // namespace vorodg
