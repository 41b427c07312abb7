#pragma once
// The one least-squares convergence-rate fit behind every rate vorodg reports: the slope of
// log(e) against log(h), its intercept and a 95% confidence half-width from Student's t. The
// plots read these numbers from summary.json; nothing fits again.
#include <optional>
#include <vector>

namespace vorodg {

struct RateFit {
  double rate = 0.0;           // slope of log(e) against log(h)
  double intercept = 0.0;      // the fitted log(e) at log(h) = 0: e ~ exp(intercept) h^rate
  std::optional<double> ci95;  // half-width of the 95% interval of the rate (needs >= 3 points)
  int points = 0;
};

/// Fits log(e) = intercept + rate log(h) over the pairs (h[i], e[i]), all > 0. Throws
/// std::invalid_argument for fewer than two points or sizes that differ.
RateFit fit_rate(const std::vector<double>& h, const std::vector<double>& e);

/// The rate between two consecutive levels: log(e0 / e1) / log(h0 / h1).
double pair_rate(double h0, double e0, double h1, double e1);

}  // namespace vorodg
