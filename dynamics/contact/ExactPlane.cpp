#include "dynamics/contact/ExactPlane.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/io/StateArchive.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {

ExactPlane::ExactPlane(const Point& point, const Point& normal, const ContactFriction& friction)
    : plane_(point, normal, "exact plane"), friction_(friction) {}

ContactReport ExactPlane::constrain(const SurfaceCells& surface, KinematicState& state) {
  const PolygonMesh& mesh = surface.mesh();
  check_state(mesh, state, "exact plane");
  seen_.resize(state.velocity.size(), -1);
  ++evaluation_;
  touched_.clear();
  ContactReport report;
  const Point tangent(-plane_.normal.y(), plane_.normal.x());
  // A pair farther from the plane than any node can move this step stays in front of it: passed
  // over on its position alone (a sequential read), without its node's velocity (a scattered
  // one). Twice the reach and a margin of round-off on the coordinates keep the test on the
  // safe side of the predicted gap's own rounding. A NaN gap is never passed over.
  const double reach = 2.0 * state.dt * state.max_speed();
  for (int c : surface.cells()) {
    ++report.candidates;
    for (int p = mesh.offsets()[c]; p < mesh.offsets()[c + 1]; ++p) {
      const Point& x = state.position[p];
      if (gap(x) > reach + 1e-12 * (1.0 + x.lpNorm<Eigen::Infinity>() +
                                    plane_.point.lpNorm<Eigen::Infinity>()))
        continue;
      const int i = state.node[p];
      if (seen_[i] == evaluation_) continue;
      seen_[i] = evaluation_;
      const double ahead = gap(state.predicted(p));
      if (!std::isfinite(ahead))
        throw NumericalError("exact plane: cell " + std::to_string(c) +
                             " has a non-finite vertex position or velocity");
      if (ahead >= 0.0 || state.inverse_mass[i] == 0.0) continue;
      const double m = 1.0 / state.inverse_mass[i];
      // Normal: land on the plane, the approach velocity gone.
      const Point jn = m * (-ahead / state.dt) * plane_.normal;
      // Friction: stop the sliding the node would do, within mu |J_n|.
      const double stick = -m * (state.velocity[i] + jn / m).dot(tangent);
      const double limit = friction_.mu() * jn.norm();
      const double jt = std::clamp(stick, -limit, limit);
      report.sliding += std::abs(stick) > limit && friction_.active();
      state.apply(i, jn, jt * tangent);
      touched_.push_back(p);
      ++report.contacts;
      report.max_depth = std::max(report.max_depth, -gap(state.position[p]));
    }
  }
  return report;
}

void ExactPlane::archive(StateArchive& a) {
  KinematicContactLaw::archive(a);
  a.vector("exact_plane.seen", seen_);
  a.value("exact_plane.evaluation", evaluation_);
}

}  // namespace vorodg
