#include "verification/report/Wasserstein.hpp"

#include <cmath>

#include "verification/report/CheckedSample.hpp"

namespace vorodg {

double wasserstein1(std::vector<double> a, std::vector<double> b) {
  a = sorted_sample("Wasserstein distance", std::move(a));
  b = sorted_sample("Wasserstein distance", std::move(b));
  const double n = static_cast<double>(a.size()), m = static_cast<double>(b.size());
  // Walk the pooled points in order; between two of them both CDFs are constant.
  std::size_t i = 0, j = 0;
  double x = std::min(a[0], b[0]), distance = 0.0;
  while (i < a.size() || j < b.size()) {
    while (i < a.size() && a[i] <= x) ++i;
    while (j < b.size() && b[j] <= x) ++j;
    if (i == a.size() && j == b.size()) break;
    const double next = std::min(i < a.size() ? a[i] : b[j], j < b.size() ? b[j] : a[i]);
    distance += std::abs(static_cast<double>(i) / n - static_cast<double>(j) / m) * (next - x);
    x = next;
  }
  return distance;
}

}  // namespace vorodg
