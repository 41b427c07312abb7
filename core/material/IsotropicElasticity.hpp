#pragma once
// Isotropic linear elasticity in plane stress or plane strain, in Voigt form
// (sigma_xx, sigma_yy, sigma_xy) = D (eps_xx, eps_yy, 2 eps_xy).
#include <Eigen/Core>

namespace vorodg {

enum class PlaneModel { stress, strain };

class IsotropicElasticity {
 public:
  /// Throws InputError unless E > 0 and -1 < nu < 0.5 (nu may come as close to 0.5 as wanted).
  IsotropicElasticity(double E, double nu, PlaneModel model);

  double E() const { return E_; }
  double nu() const { return nu_; }
  PlaneModel model() const { return model_; }
  /// Lame constants of the 3D material (plane strain uses them as they are).
  double lambda() const { return E_ * nu_ / ((1 + nu_) * (1 - 2 * nu_)); }
  double mu() const { return E_ / (2 * (1 + nu_)); }
  /// In-plane constitutive matrix.
  const Eigen::Matrix3d& D() const { return D_; }
  /// Von Mises stress of an in-plane stress state (sxx, syy, sxy); in plane strain sigma_zz =
  /// nu (sxx + syy) enters it, in plane stress it is zero.
  double von_mises(const Eigen::Vector3d& stress) const;

 private:
  double E_, nu_;
  PlaneModel model_;
  Eigen::Matrix3d D_;
};

}  // namespace vorodg
