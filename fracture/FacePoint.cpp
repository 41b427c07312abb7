#include "fracture/FacePoint.hpp"

#include <algorithm>
#include <cmath>

#include "core/material/CoulombFriction.hpp"

namespace vorodg {

void add_closure(double k, double gn, FacePointResponse& r) {
  if (gn >= 0.0) return;
  r.traction[0] += k * gn;
  r.tangent(0, 0) += k;
}

double closure_energy(double k, double gn) {
  const double overlap = std::min(gn, 0.0);
  return 0.5 * k * overlap * overlap;
}

void add_friction(double mu, double k, double gn, double gt, FrictionState& friction,
                  FacePointResponse& r) {
  if (mu == 0.0) return;
  if (gn >= 0.0) {  // open: no pressure, no friction; it closes again unstressed
    friction.dissipated += 0.5 * friction.shear * (gt - friction.slip);  // the spring let go
    friction.slip = gt;
    friction.shear = 0.0;
    return;
  }
  const double limit = mu * k * -gn;  // mu p
  const CoulombReturn c = coulomb_return(k * (gt - friction.slip), limit, k);
  r.traction[1] += c.shear;
  const double previous = friction.shear;
  friction.shear = c.shear;
  if (!c.slipping()) {
    r.tangent(1, 1) += k;
    return;
  }
  friction.dissipated += 0.5 * (previous + c.shear) * c.slip;
  friction.slip += c.slip;
  r.tangent(1, 0) -= std::copysign(mu * k, c.shear);  // d(mu k (-gn)) / d gn, signed
}

double friction_stored_energy(double mu, double k, double gn, double gt,
                              const FrictionState& friction) {
  if (mu == 0.0 || gn >= 0.0) return 0.0;
  const double stretch = gt - friction.slip;
  return 0.5 * k * stretch * stretch;
}

FacePointResponse face_point_response(const CohesiveLaw& law, const Eigen::Vector2d& d, double k,
                                      CohesiveLaw::State& history) {
  const CohesiveLaw::Response r = law.respond(d, history);
  FacePointResponse out{r.traction, r.tangent};
  add_closure(k, d[0], out);
  return out;
}

double face_point_stored_energy(const CohesiveLaw& law, const Eigen::Vector2d& d, double k,
                                const CohesiveLaw::State& history) {
  return law.stored_energy(d, history) + closure_energy(k, d[0]);
}

}  // namespace vorodg
