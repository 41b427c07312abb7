#include "verification/report/Extrapolation.hpp"

#include <cmath>

#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

/// The linear least-squares fit of q = limit + c h^rate for a given rate.
Extrapolation fit_at(const std::vector<double>& h, const std::vector<double>& q, double rate) {
  const double n = static_cast<double>(h.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double x = std::pow(h[i], rate);
    sx += x, sy += q[i], sxx += x * x, sxy += x * q[i];
  }
  Extrapolation e;
  e.rate = rate;
  const double det = n * sxx - sx * sx;
  e.coefficient = det != 0.0 ? (n * sxy - sx * sy) / det : 0.0;
  e.limit = (sy - e.coefficient * sx) / n;
  double ss = 0.0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double r = q[i] - e.limit - e.coefficient * std::pow(h[i], rate);
    ss += r * r;
  }
  e.residual = std::sqrt(ss / n);
  return e;
}

}  // namespace

Extrapolation extrapolate(const std::vector<double>& h, const std::vector<double>& q) {
  if (h.size() != q.size() || h.size() < 3)
    throw InputError("extrapolation: expected at least three levels with one value each, found " +
                     std::to_string(h.size()) + " sizes and " + std::to_string(q.size()) +
                     " values");
  for (std::size_t i = 0; i < h.size(); ++i)
    if (!(h[i] > 0.0) || !std::isfinite(h[i]) || !std::isfinite(q[i]))
      throw InputError("extrapolation: level " + std::to_string(i) +
                       " needs h > 0 and finite values");
  // Coarse scan (the misfit can have several local minima), then golden section around the best.
  constexpr int kScan = 60;
  double best = kMinRate, best_residual = INFINITY;
  for (int k = 0; k <= kScan; ++k) {
    const double rate = kMinRate + (kMaxRate - kMinRate) * k / kScan;
    const double r = fit_at(h, q, rate).residual;
    if (r < best_residual) best_residual = r, best = rate;
  }
  const double step = (kMaxRate - kMinRate) / kScan;
  double a = std::max(kMinRate, best - step), b = std::min(kMaxRate, best + step);
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int k = 0; k < 100 && b - a > 1e-12; ++k) {
    const double c = b - golden * (b - a), d = a + golden * (b - a);
    if (fit_at(h, q, c).residual < fit_at(h, q, d).residual)
      b = d;
    else
      a = c;
  }
  return fit_at(h, q, 0.5 * (a + b));
}

}  // namespace vorodg
