#include "core/random/FieldMarginal.hpp"

#include <algorithm>
#include <cmath>

#include "core/util/Errors.hpp"

namespace vorodg {

MarginalKind marginal_kind(const std::string& name) {
  if (name == "uniform") return MarginalKind::uniform;
  if (name == "weibull") return MarginalKind::weibull;
  throw InputError("marginal '" + name + "': expected uniform or weibull");
}

std::string marginal_name(MarginalKind kind) {
  return kind == MarginalKind::weibull ? "weibull" : "uniform";
}

void FieldMarginal::check() const {
  if (kind == MarginalKind::uniform && !(half_width >= 0.0 && half_width < 1.0))
    throw InputError("random field: uniform half-width " + std::to_string(half_width) +
                     ": expected 0 <= a < 1 (a positive factor)");
  if (kind == MarginalKind::weibull && !(std::isfinite(shape) && shape > 0.0))
    throw InputError("random field: Weibull shape " + std::to_string(shape) + ": expected > 0");
}

double FieldMarginal::operator()(double g) const {
  if (kind == MarginalKind::uniform) {
    const double u = 0.5 * std::erfc(-g / std::sqrt(2.0));
    return 1.0 - half_width + 2.0 * half_width * u;
  }
  // -ln(1 - u) = -ln(Phi(-g)), computed from erfc so that the upper tail keeps its digits.
  const double tail = -std::log(0.5 * std::erfc(g / std::sqrt(2.0)));
  return std::pow(tail, 1.0 / shape) / std::tgamma(1.0 + 1.0 / shape);
}

double FieldMarginal::cdf(double x) const {
  if (kind == MarginalKind::uniform) {
    if (half_width == 0.0) return x >= 1.0 ? 1.0 : 0.0;
    return std::clamp((x - (1.0 - half_width)) / (2.0 * half_width), 0.0, 1.0);
  }
  if (x <= 0.0) return 0.0;
  const double scaled = x * std::tgamma(1.0 + 1.0 / shape);
  return 1.0 - std::exp(-std::pow(scaled, shape));
}

}  // namespace vorodg
