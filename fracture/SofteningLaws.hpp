#pragma once
// The softening envelopes of the cohesive law (CohesiveLaw), by name: each is a piecewise-linear
// curve T(delta) from the peak (delta_0, sigma_c) down to zero at the critical opening, with the
// area G under the whole envelope (the elastic branch of an intrinsic law included). An entry
// gives the knots after the peak; the law puts (0, 0) and the peak before them and checks that
// the openings increase. A new envelope is one entry: in SofteningLaws.cpp's table, or
// register_softening_law from anywhere (as a test does); scenes name it as `cohesive.law`.
#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

namespace vorodg {

struct SofteningLawEntry {
  std::string name;  // as scenes name it
  std::string doc;   // one line
  /// The knots (delta, T) after the peak, the last at T = 0, for strength sigma_c, fracture
  /// energy G and the peak's opening delta_0 (0 for an extrinsic law).
  std::function<std::vector<Eigen::Vector2d>(double strength, double energy, double peak_opening)>
      knots_after_peak;
};

/// Every softening envelope known, in registration order: the shipped ones first.
const std::vector<SofteningLawEntry>& softening_laws();
/// Adds one (a name already known is refused with InputError); returns true, for registering at
/// static initialization.
bool register_softening_law(SofteningLawEntry entry);
/// The envelope named `name`; throws InputError for an unknown name.
const SofteningLawEntry& softening_law(const std::string& name);
/// "linear or bilinear": the names, for messages and key tables.
std::string softening_law_list();
/// " linear bilinear ... ": the names, each with a space either side (for scene readers).
std::string softening_law_words();

}  // namespace vorodg
