#pragma once
// The Mohr-Coulomb crack-initiation criterion with a tensile cutoff (report Eq. 22 and its
// Figure 11): a plane fails when the shear traction on it reaches c - mu sigma, or its normal
// traction sigma (tension positive) reaches the cutoff sigma_o. Compression raises the shear the
// plane can carry; a friction-free criterion (mu = 0) is a plain shear limit.
namespace vorodg {

struct MohrCoulombParameters {
  double cohesion = 0.0;        // c > 0
  double friction = 0.0;        // mu >= 0
  double tensile_cutoff = 0.0;  // sigma_o > 0
};

class MohrCoulomb {
 public:
  /// Throws InputError naming the parameter unless c > 0, mu >= 0 and sigma_o > 0 (finite).
  explicit MohrCoulomb(const MohrCoulombParameters& parameters);

  const MohrCoulombParameters& parameters() const { return p_; }
  /// How close the traction (sigma, tau) on a plane is to failure: the larger of sigma / sigma_o
  /// and |tau| / (c - mu sigma) (infinite where c - mu sigma <= 0). At least 1 means it fails;
  /// comparing it orders interfaces by how far past the criterion they are.
  double utilization(double normal, double shear) const;
  bool fails(double normal, double shear) const { return utilization(normal, shear) >= 1.0; }
  /// The worst plane through a point of plane stress (Voigt xx, yy, xy): the least strength
  /// factor f for which the point's Mohr circle (centre p, radius R) still touches the criterion
  /// scaled by f,
  ///     max((p + R) / sigma_o, (mu p + R sqrt(1 + mu^2)) / c).
  /// Below it no plane fails: sigma_n / f < sigma_o and (|tau| + mu sigma_n) / f < c on every
  /// plane. Both are linear or convex in the stress, so a mean of stresses that each lie below f
  /// lies below f too (the insertion check screens edges with it).
  double worst_plane_factor(double sxx, double syy, double sxy) const;

 private:
  MohrCoulombParameters p_;
  double circle_reach_;  // sqrt(1 + mu^2): the most |tau| + mu sigma_n gains per unit radius
};

}  // namespace vorodg
