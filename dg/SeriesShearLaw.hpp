#pragma once
// The extrinsic cohesive law with the coupling's penalty spring in series in shear
// (docs/fracture.md "Interface states"). The law's sliding secant beta^2 T(delta) / delta grows
// without bound as the effective opening vanishes, and a face that opens while sheared would see
// its traction and its energy jump (from the sticking branch's eps g_t to the law's beta T). Here
// the tangential opening g_t splits into the law's part x and a spring's part g_t - x, with the
// same shear traction in both:
//     law_t(g_n, x) = eps (g_t - x),
// so that the face's energy is the law's closed form at (g_n, x) plus eps (g_t - x)^2 / 2, the
// tractions derive from it, the sliding stiffness never exceeds eps, and a face that has not
// opened (x = 0) meets the sticking branch continuously in traction and in energy. The normal
// traction is the law's at (g_n, x). For a fresh face at g_n <= 0 the sticking branch applies
// instead (CohesiveInterfaces). x lies between 0 and g_t and is the one root of a monotone
// function as long as eps exceeds beta^2 times the envelope's steepest softening slope (else
// the bracketed search still returns a root).
#include <Eigen/Core>

#include "fracture/CohesiveLaw.hpp"

namespace vorodg {

struct SeriesShearResponse {
  Eigen::Vector2d traction;  // (normal, tangential)
  Eigen::Matrix2d tangent;   // d traction / d opening, with x eliminated
  double law_shear = 0.0;    // x: the law's share of the tangential opening
};

/// The response at opening d (normal, tangential); advances `state` on the envelope at (d_n, x).
SeriesShearResponse series_shear_respond(const CohesiveLaw& law, double eps,
                                         const Eigen::Vector2d& d, CohesiveLaw::State& state);
/// The recoverable energy per unit area at opening d for a point whose history is `state` (after
/// the response that reached d): the law's stored energy at (d_n, x) plus eps (d_t - x)^2 / 2.
double series_shear_stored_energy(const CohesiveLaw& law, double eps, const Eigen::Vector2d& d,
                                  const CohesiveLaw::State& state);

}  // namespace vorodg
