#include "fracture/FacePoint.hpp"

#include <algorithm>

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
