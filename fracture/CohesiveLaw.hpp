#pragma once
// An extrinsic cohesive law for crack faces (after Camacho and Ortiz): the traction softens from
// the strength sigma_c at zero opening to nothing at the critical opening delta_c, as a function
// of the effective opening
//   delta = sqrt(<delta_n>^2 + beta^2 delta_t^2),  <x> = max(x, 0),
// which weighs sliding by the shear factor beta. The traction is t = (T / delta) (<delta_n>,
// beta^2 delta_t), so that t . d(delta_n, delta_t) = T d(delta) on any path and the work of
// separation is the area under the envelope T(delta): the fracture energy G, whatever the mode
// mix. Unloading (delta below its largest value so far, delta_max) goes linearly towards the
// origin, and so does reloading until delta_max. A closed crack (delta_n < 0) carries no normal
// traction: preventing interpenetration is contact's job, not the law's.
// The envelope's shape after the peak is a softening law, chosen by name (SofteningLaws):
//   linear:   T = sigma_c (1 - delta / delta_c),  delta_c = 2 G / sigma_c
//   bilinear: the usual concrete law, kink at sigma_c / 3: T falls from sigma_c to sigma_c / 3 at
//             delta_1 = 0.8 G / sigma_c, then to zero at delta_c = 3.6 G / sigma_c (area G)
// An intrinsic law (initial_stiffness K0 > 0) puts an elastic branch T = K0 delta before the
// peak, reached at delta_0 = sigma_c / K0; the softening keeps the area G: linear from
// (delta_0, sigma_c) to (delta_c, 0), bilinear with its kink moved to delta_1 + delta_0 / 3.
// The law is the same for quasi-static fracture and for dynamic fragmentation.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace vorodg {

struct CohesiveParameters {
  double strength = 0.0;           // sigma_c > 0
  double fracture_energy = 0.0;    // G > 0: the area under the envelope
  double shear_factor = 1.0;       // beta >= 0
  std::string shape = "linear";    // the softening law's name (SofteningLaws)
  double initial_stiffness = 0.0;  // K0: 0 for an extrinsic law, > 0 for an intrinsic one
};

class CohesiveLaw {
 public:
  /// Throws InputError naming the parameter unless sigma_c > 0, G > 0, beta >= 0 and K0 >= 0
  /// (finite), and an intrinsic law's peak comes before its critical opening.
  explicit CohesiveLaw(const CohesiveParameters& parameters);

  const CohesiveParameters& parameters() const { return p_; }
  /// The law of a face whose strength is `factor` times this one's (a material varying in
  /// space): sigma_c scaled; G, beta and K0 unchanged, so delta_c scales by 1 / factor.
  /// Throws InputError as the constructor does for the scaled strength.
  CohesiveLaw with_strength_factor(double factor) const;
  /// delta_c: the effective opening at which the traction vanishes for good.
  double critical_opening() const;
  bool intrinsic() const { return p_.initial_stiffness > 0.0; }
  /// T(delta) on the envelope (0 beyond delta_c).
  double envelope(double opening) const;
  /// dT/d(delta) on the envelope (the slope of the segment delta lies on; 0 beyond delta_c).
  double envelope_slope(double opening) const;

  /// The history of one interface point: the largest effective opening so far.
  struct State {
    double max_opening = 0.0;
  };
  struct Response {
    Eigen::Vector2d traction;  // (normal, tangential), the face's frame
    Eigen::Matrix2d tangent;   // d traction / d opening, consistent with the branch taken
    double effective_opening = 0.0;
    bool loading = false;  // on the envelope (delta >= delta_max), not on the unloading line
  };
  /// The traction for the opening (normal, tangential); advances `state` on the envelope.
  Response respond(const Eigen::Vector2d& opening, State& state) const;
  /// Recoverable energy per unit area at `opening` (normal, tangential), for a point whose
  /// largest effective opening so far is state.max_opening: the triangle under the unloading
  /// line through the origin, (T(delta_max) / delta_max) delta^2 / 2 (an intrinsic law before
  /// any opening: K0 delta^2 / 2; an extrinsic one that never opened stores nothing).
  double stored_energy(const Eigen::Vector2d& opening, const State& state) const;
  /// Energy dissipated per unit area once the effective opening has reached `max_opening`: the
  /// area under the envelope up to it, less what unloading to the origin gives back; G when
  /// fully separated.
  double dissipated_energy(double max_opening) const;

 private:
  int segment(double opening) const;  // the envelope piece opening lies on, or -1 beyond it
  CohesiveParameters p_;
  // The envelope as a polyline (opening, traction), ending at (delta_c, 0).
  std::vector<Eigen::Vector2d> knots_;
};

}  // namespace vorodg
