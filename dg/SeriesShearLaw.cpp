#include "dg/SeriesShearLaw.hpp"

#include <algorithm>
#include <cmath>

#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

constexpr int kIterations = 100;

/// The law's part x of the tangential opening: the root of law_t(d_n, x) - eps (d_t - x) in
/// [min(0, d_t), max(0, d_t)], by Newton kept inside a shrinking bracket (bisection when a Newton
/// step would leave it). The history is not advanced here.
double law_shear(const CohesiveLaw& law, double eps, const Eigen::Vector2d& d,
                 const CohesiveLaw::State& state) {
  if (d[1] == 0.0) return 0.0;
  double lo = std::min(0.0, d[1]), hi = std::max(0.0, d[1]);
  const double sign = d[1] > 0.0 ? 1.0 : -1.0;  // F < 0 towards 0, > 0 towards d_t (times sign)
  double x = d[1];
  const double scale = eps * std::abs(d[1]) + law.parameters().strength;
  for (int k = 0; k < kIterations; ++k) {
    CohesiveLaw::State trial = state;
    const CohesiveLaw::Response r = law.respond(Eigen::Vector2d(d[0], x), trial);
    const double F = r.traction[1] - eps * (d[1] - x);
    if (std::abs(F) <= 1e-13 * scale || hi - lo <= 1e-15 * std::abs(d[1])) return x;
    if (sign * F > 0.0)
      (sign > 0 ? hi : lo) = x;
    else
      (sign > 0 ? lo : hi) = x;
    const double slope = r.tangent(1, 1) + eps;
    const double next = slope > 0.0 ? x - F / slope : 0.5 * (lo + hi);
    x = next > lo && next < hi ? next : 0.5 * (lo + hi);
  }
  throw NumericalError("cohesive law in series with the shear penalty: no root after 100 steps");
}

}  // namespace

SeriesShearResponse series_shear_respond(const CohesiveLaw& law, double eps,
                                         const Eigen::Vector2d& d, CohesiveLaw::State& state) {
  SeriesShearResponse out;
  out.law_shear = law_shear(law, eps, d, state);
  const CohesiveLaw::Response r = law.respond(Eigen::Vector2d(d[0], out.law_shear), state);
  const Eigen::Matrix2d& L = r.tangent;
  // dx from d(law_t - eps (d_t - x)) = 0: (L_tt + eps) dx = eps dd_t - L_tn dd_n.
  const double s = L(1, 1) + eps;
  out.traction = Eigen::Vector2d(r.traction[0], eps * (d[1] - out.law_shear));
  out.tangent(0, 0) = L(0, 0) - L(0, 1) * L(1, 0) / s;
  out.tangent(0, 1) = L(0, 1) * eps / s;
  out.tangent(1, 0) = eps * L(1, 0) / s;
  out.tangent(1, 1) = eps * L(1, 1) / s;
  return out;
}

double series_shear_stored_energy(const CohesiveLaw& law, double eps, const Eigen::Vector2d& d,
                                  const CohesiveLaw::State& state) {
  const double x = law_shear(law, eps, d, state);
  const double spring = d[1] - x;
  return law.stored_energy(Eigen::Vector2d(d[0], x), state) + 0.5 * eps * spring * spring;
}

}  // namespace vorodg
