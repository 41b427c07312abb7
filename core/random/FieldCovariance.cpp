#include "core/random/FieldCovariance.hpp"

#include <cmath>

#include "core/util/Errors.hpp"

namespace vorodg {

CovarianceKind covariance_kind(const std::string& name) {
  if (name == "squared-exponential") return CovarianceKind::squared_exponential;
  if (name == "matern") return CovarianceKind::matern;
  throw InputError("covariance '" + name + "': expected squared-exponential or matern");
}

std::string covariance_name(CovarianceKind kind) {
  return kind == CovarianceKind::matern ? "matern" : "squared-exponential";
}

void FieldCovariance::check() const {
  if (!(std::isfinite(length) && length > 0.0))
    throw InputError("random field: correlation length " + std::to_string(length) +
                     ": expected > 0");
  if (kind == CovarianceKind::matern && !(std::isfinite(smoothness) && smoothness > 0.0))
    throw InputError("random field: Matern smoothness " + std::to_string(smoothness) +
                     ": expected > 0");
}

double FieldCovariance::operator()(double r) const {
  const double x = std::abs(r) / length;
  if (kind == CovarianceKind::squared_exponential) return std::exp(-0.5 * x * x);
  const double s = std::sqrt(2.0 * smoothness) * x;
  if (s == 0.0) return 1.0;
  // Past s = 700 K_nu underflows; the correlation is zero to double precision long before.
  if (s > 700.0) return 0.0;
  return std::pow(2.0, 1.0 - smoothness) / std::tgamma(smoothness) * std::pow(s, smoothness) *
         std::cyl_bessel_k(smoothness, s);
}

}  // namespace vorodg
