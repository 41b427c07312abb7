#include "verification/report/RateFit.hpp"

#include <cmath>
#include <stdexcept>

#include "verification/report/Distributions.hpp"

namespace vorodg {

double pair_rate(double h0, double e0, double h1, double e1) {
  return std::log(e0 / e1) / std::log(h0 / h1);
}

RateFit fit_rate(const std::vector<double>& h, const std::vector<double>& e) {
  const std::size_t n = h.size();
  if (n < 2 || e.size() != n)
    throw std::invalid_argument("fit_rate: expected two or more (h, e) pairs");
  // Means, then centred sums: the order of these operations fixes the published digits.
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) mx += std::log(h[i]) / n, my += std::log(e[i]) / n;
  double sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (std::log(h[i]) - mx) * (std::log(h[i]) - mx);
    sxy += (std::log(h[i]) - mx) * (std::log(e[i]) - my);
  }
  RateFit fit;
  fit.points = static_cast<int>(n);
  fit.rate = sxy / sxx;
  fit.intercept = my - fit.rate * mx;
  if (n > 2) {
    double ss = 0;  // residual sum of squares
    for (std::size_t i = 0; i < n; ++i) {
      const double residual = std::log(e[i]) - (my + fit.rate * (std::log(h[i]) - mx));
      ss += residual * residual;
    }
    const double se = std::sqrt(ss / (n - 2) / sxx);  // standard error of the slope
    const double half_width = student_t_quantile(0.975, static_cast<double>(n - 2)) * se;
    if (std::isfinite(half_width)) fit.ci95 = half_width;
  }
  return fit;
}

}  // namespace vorodg
