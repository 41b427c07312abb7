#pragma once
// Coulomb friction regularized by a stick spring: the return mapping every frictional surface of
// the code uses (crack faces in fracture/FacePoint, contact in dynamics/contact), written once.
//
// While two surfaces stick, the shear they carry is that of an elastic spring of stiffness k on
// their relative tangential motion (the "trial" shear, what the spring would carry if nothing
// slipped). Coulomb's law bounds it by mu p, p the normal pressure: where the trial passes the
// limit, the surfaces slip by just enough for the spring to carry mu p, as a plastic return
// mapping does. The slip is then (trial - shear) / k, and the work it takes, mu p |slip|, is
// dissipated; the spring's own energy shear^2 / (2 k) is stored. As k grows the spring's
// stretch mu p / k vanishes and this is Coulomb's law with its exact stick-slip switch.
#include <cmath>

namespace vorodg {

struct CoulombReturn {
  double shear = 0.0;  // what the surfaces carry: the trial, or the limit with its sign
  double slip = 0.0;   // signed tangential slip of this increment: (trial - shear) / k
  /// The work the slip took, limit |slip| (0 while sticking).
  double dissipated = 0.0;
  bool slipping() const { return slip != 0.0; }
};

/// The return mapping: `trial` the stick spring's shear, `limit` = mu p >= 0, `stiffness` k > 0.
inline CoulombReturn coulomb_return(double trial, double limit, double stiffness) {
  if (std::abs(trial) <= limit) return {trial, 0.0, 0.0};
  const double shear = std::copysign(limit, trial);
  const double slip = (trial - shear) / stiffness;
  return {shear, slip, limit * std::abs(slip)};
}

}  // namespace vorodg
