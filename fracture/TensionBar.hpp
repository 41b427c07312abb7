#pragma once
// The tension bar's closed form (docs/fracture.md "Problems"): u_x = 0 on the left side, u_y = 0
// along the bottom (rollers), u_x = stroke on the right side; the crack line is vertical at
// line_x. With u_y fixed at the lower-left corner only, a bar long enough to snap back also
// bends: the crack opens more at one end (a bifurcation the 1D closed form ignores). Rollers keep
// it on the uniform path. Elastic up to sigma_c, then sigma = T(w) with stroke = sigma L / E' + w
// (E' = E in plane stress, E / (1 - nu^2) in plane strain).
#include "fracture/FractureProblem.hpp"

namespace vorodg {

/// The tension bar's closed form at crack opening w: (stroke, load in newtons).
struct BarResponse {
  double stroke, load;
};
BarResponse tension_bar_closed_form(const FractureGeometry& g, const IsotropicElasticity& material,
                                    const CohesiveLaw& law, double thickness, double opening);
/// Openings below this fraction of delta_c count as an intact bar.
inline constexpr double kIntactOpening = 1e-9;
/// How far a point of the bar's path lies from the closed form: the larger of the load's deviation
/// over the strength's load sigma_c H t and the stroke's relative deviation. An intact bar is
/// compared with its elastic line.
double tension_bar_deviation(const FractureGeometry& g, const IsotropicElasticity& material,
                             const CohesiveLaw& law, double thickness, double stroke,
                             double opening, double load);

}  // namespace vorodg
