#include "dynamics/contact/RigidPlane.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_set>

#include "core/io/StateArchive.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {

RigidPlane::RigidPlane(const Point& point, const Point& normal, const PenaltyContact& law,
                       const ContactFriction& friction)
    : plane_(point, normal, "rigid plane"), law_(law), friction_(friction) {}

ContactReport RigidPlane::add_forces(const SurfaceCells& surface, const PairState& state,
                                     std::span<Point> force, std::span<Point> velocity_force) {
  const PolygonMesh& mesh = surface.mesh();
  check_pair_state(mesh, state, "rigid plane");
  law_.check(state, "rigid plane");
  if (force.size() != state.position.size())
    throw InputError("rigid plane: " + std::to_string(force.size()) +
                     " force entries: expected one per (cell, vertex) pair, " +
                     std::to_string(state.position.size()));
  ContactReport report;
  shear_next_.clear();
  touched_.clear();
  // Penetrating pairs are few: a set of their nodes is cheaper than a flag per node.
  std::unordered_set<int> taken;
  constexpr double kRigid = std::numeric_limits<double>::infinity();
  for (int c : surface.cells()) {
    ++report.candidates;
    for (int p = mesh.offsets()[c]; p < mesh.offsets()[c + 1]; ++p) {
      const double depth = -gap(state.position[p]);
      if (!std::isfinite(depth))
        throw NumericalError("rigid plane: cell " + std::to_string(c) +
                             " has a non-finite vertex position");
      if (depth <= 0.0 || !taken.insert(state.node_of(p)).second) continue;
      const double mass =
          state.mass.empty() ? 0.0 : PenaltyContact::reduced_mass(state.mass[p], kRigid);
      const double rate = state.velocity.empty() ? 0.0 : -state.velocity[p].dot(plane_.normal);
      const auto r = law_.respond(depth, rate, mass, state.dt);
      force[p] += r.force * plane_.normal;
      touched_.push_back(p);
      if (!velocity_force.empty()) velocity_force[p] += r.velocity_force * plane_.normal;
      if (friction_.active()) add_friction(p, r, state, force, report);
      ++report.contacts;
      report.potential += r.potential;
      report.dissipation_power += r.dissipation_power;
      report.max_depth = std::max(report.max_depth, depth);
    }
  }
  std::swap(shear_, shear_next_);
  return report;
}

void RigidPlane::add_friction(int p, const PenaltyContact::Response& normal, const PairState& state,
                              std::span<Point> force, ContactReport& report) {
  const auto known = shear_.find(p);
  double shear = known == shear_.end() ? 0.0 : known->second;
  const Point velocity = state.velocity.empty() ? Point::Zero() : state.velocity[p];
  force[p] += friction_.force(plane_.normal, velocity, normal, state, shear, report, "rigid plane");
  shear_next_.emplace(p, shear);
}

void RigidPlane::archive(StateArchive& a) {
  a.map("penalty_plane.shear", shear_);
  a.vector("penalty_plane.touched", touched_);
}

}  // namespace vorodg
