#pragma once
// The marginal distribution a material factor takes from a standard Gaussian field value g: the
// field's value is mapped through the normal CDF Phi to a uniform u = Phi(g), and u through the
// target's inverse CDF, so the factor has the target distribution exactly at every point while
// keeping the field's correlation structure (a translation field: Grigoriu 1998).
//
//   uniform, half-width a   1 - a + 2 a u: uniform on [1 - a, 1 + a] (the report's +-5 %, a = 0.05)
//   Weibull, shape k        (-ln(1 - u))^(1/k) / Gamma(1 + 1/k): mean 1, the usual weakest-link
//                           law for strength (a smaller k, a wider spread)
#include <string>

namespace vorodg {

enum class MarginalKind { uniform, weibull };

/// "uniform" or "weibull"; throws InputError naming the accepted names otherwise.
MarginalKind marginal_kind(const std::string& name);
std::string marginal_name(MarginalKind kind);

struct FieldMarginal {
  MarginalKind kind = MarginalKind::uniform;
  double half_width = 0.05;  // uniform: a in [0, 1)
  double shape = 12.0;       // Weibull: k > 0

  /// Throws InputError for a half-width outside [0, 1) or a non-positive shape.
  void check() const;
  /// The factor for a standard Gaussian value g.
  double operator()(double g) const;
  /// The factor's CDF at x (for tests and reports).
  double cdf(double x) const;
};

}  // namespace vorodg
