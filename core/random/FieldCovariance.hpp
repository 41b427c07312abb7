#pragma once
// The correlation of a stationary, isotropic random field as a function of distance, rho(r), with
// rho(0) = 1 (the field's variance is a separate factor). Two families, both standard in the
// random-field literature (Rasmussen and Williams 2006, ch. 4; Lord, Powell and Shardlow 2014):
//
//   squared exponential   rho(r) = exp(-r^2 / (2 l^2))
//   Matern, smoothness nu rho(r) = 2^(1 - nu) / Gamma(nu) s^nu K_nu(s),  s = sqrt(2 nu) r / l
//
// with l the correlation length. Matern with nu = 1/2 is the exponential exp(-r / l); as nu grows
// its realizations get smoother (ceil(nu) - 1 times differentiable), and nu -> infinity is the
// squared exponential. The half-integer smoothnesses have closed forms, which the tests use to
// check the Bessel-function form.
#include <string>

namespace vorodg {

enum class CovarianceKind { squared_exponential, matern };

/// "squared-exponential" or "matern"; throws InputError naming the accepted names otherwise.
CovarianceKind covariance_kind(const std::string& name);
std::string covariance_name(CovarianceKind kind);

struct FieldCovariance {
  CovarianceKind kind = CovarianceKind::squared_exponential;
  double length = 1.0;      // correlation length l > 0
  double smoothness = 1.5;  // Matern's nu > 0 (unused by the squared exponential)

  /// Throws InputError for a non-positive or non-finite length or smoothness.
  void check() const;
  /// rho(r) for r >= 0.
  double operator()(double r) const;
};

}  // namespace vorodg
