#include "verification/report/KolmogorovSmirnov.hpp"

#include <algorithm>
#include <cmath>

#include "verification/report/CheckedSample.hpp"

namespace vorodg {

double kolmogorov_survival(double x) {
  if (x < 1e-3) return 1.0;
  double sum = 0.0, sign = 1.0;
  for (int k = 1; k <= 200; ++k) {
    const double term = sign * std::exp(-2.0 * k * k * x * x);
    sum += term;
    if (std::abs(term) < 1e-16 * std::abs(sum)) break;
    sign = -sign;
  }
  return std::clamp(2.0 * sum, 0.0, 1.0);
}

KsResult ks_two_sample(std::vector<double> a, std::vector<double> b) {
  a = sorted_sample("Kolmogorov-Smirnov", std::move(a));
  b = sorted_sample("Kolmogorov-Smirnov", std::move(b));
  const double n = static_cast<double>(a.size()), m = static_cast<double>(b.size());
  std::size_t i = 0, j = 0;
  KsResult r;
  while (i < a.size() && j < b.size()) {
    const double x = std::min(a[i], b[j]);
    while (i < a.size() && a[i] <= x) ++i;  // ties step both CDFs together
    while (j < b.size() && b[j] <= x) ++j;
    r.distance = std::max(r.distance, std::abs(i / n - j / m));
  }
  const double ne = std::sqrt(n * m / (n + m));
  r.p_value = kolmogorov_survival((ne + 0.12 + 0.11 / ne) * r.distance);
  return r;
}

}  // namespace vorodg
