#include "dynamics/contact/ExactSurfaceContact.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/io/StateArchive.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {

ExactSurfaceContact::ExactSurfaceContact(double grid_spacing, const ContactFriction& friction)
    : friction_(friction), search_(grid_spacing), spacing_(grid_spacing) {}

ContactReport ExactSurfaceContact::constrain(const SurfaceCells& surface, KinematicState& state) {
  const PolygonMesh& mesh = surface.mesh();
  check_state(mesh, state, "exact surface contact");
  predicted_.resize(state.position.size(), Point::Zero());
  for (int c : surface.cells())
    for (int p = mesh.offsets()[c]; p < mesh.offsets()[c + 1]; ++p)
      predicted_[p] = state.predicted(p);
  search_.find(surface, predicted_);
  taken_.clear();
  touched_.clear();
  contacts_.clear();
  ContactReport report;
  report.candidates = static_cast<int>(search_.surface_pairs().size());
  for (const IndexPair& ij : search_.surface_pairs()) {
    find_contacts(surface, ij.first, ij.second, state, report);
    find_contacts(surface, ij.second, ij.first, state, report);
  }
  solve(state, report);
  return report;
}

void ExactSurfaceContact::find_contacts(const SurfaceCells& surface, int i, int j,
                                        const KinematicState& state, ContactReport& report) {
  const PolygonMesh& mesh = surface.mesh();
  const int a = surface.cells()[i], b = surface.cells()[j];
  const int base_a = mesh.offsets()[a], base_b = mesh.offsets()[b], nb = mesh.cell_size(b);
  const auto exits =
      surface.has_exposed_edge(b) ? surface.exposed_edges(b) : std::span<const char>{};
  const Box& box_b = search_.box(j);
  for (int k = 0; k < mesh.cell_size(a); ++k) {
    const int p = base_a + k;
    if (!box_b.contains(predicted_[p])) continue;  // most candidates never touch
    const auto pen = PolygonPenetration::of_point(predicted_[p],
                                                  SurfaceSearch::loop(mesh, predicted_, b), exits);
    if (!pen) continue;
    if (pen->depth > SurfaceSearch::kTunnelDepth * std::sqrt(mesh.cell_area(b))) {
      ++report.tunnelled;
      continue;
    }
    const std::uint64_t key =
        (static_cast<std::uint64_t>(state.node[p]) << 32) | static_cast<std::uint32_t>(b);
    if (!taken_.insert(key).second) continue;  // this node is already kept out of b
    Contact c;
    c.p = p, c.e0 = base_b + pen->edge, c.e1 = base_b + (pen->edge + 1) % nb;
    c.t = pen->t, c.normal = pen->normal;
    // A vertex behind this edge now: stop it going deeper, never push it out (see the header).
    // Measured along the same normal and edge point as the predicted depth, so that the two
    // differ by the step's approach alone (another edge's depth would not).
    const Point q = (1.0 - c.t) * state.position[c.e0] + c.t * state.position[c.e1];
    c.inside = std::max(c.normal.dot(q - state.position[p]), 0.0);
    report.max_depth = std::max(report.max_depth, c.inside);
    report.late += c.inside > 0.0;
    const double s = 1.0 - c.t;
    c.w = state.inverse_mass[state.node[c.p]] + s * s * state.inverse_mass[state.node[c.e0]] +
          c.t * c.t * state.inverse_mass[state.node[c.e1]];
    if (c.w > 0.0) contacts_.push_back(c);  // else every node is held
  }
}

void ExactSurfaceContact::solve(KinematicState& state, ContactReport& report) {
  // Projected Gauss-Seidel on the accumulated impulses: each sweep closes every contact's
  // predicted depth at the predictions the sweep has reached, keeping the normal impulse >= 0
  // and the friction impulse within mu times it, until a sweep finds no contact still open by
  // more than kTolerance of the grid spacing (deeper, or apart while it pushes). The residual
  // is what is checked, not the impulses: two flat faces meet with each side's vertices on the
  // other's edges, constraints that agree but are redundant, along which the impulses drift
  // slowly while the positions have long converged.
  const double tolerance = kTolerance * spacing_;
  sweeps_ = 0;
  for (double open = INFINITY; open > tolerance && sweeps_ < kMaxSweeps; ++sweeps_) {
    open = 0.0;
    for (Contact& c : contacts_) open = std::max(open, relax(c, state));
  }
  for (const Contact& c : contacts_) {
    if (c.normal_impulse == 0.0) continue;
    touched_.insert(touched_.end(), {c.p, c.e0, c.e1});
    ++report.contacts;
    report.sliding +=
        friction_.active() && std::abs(c.friction_impulse) >= friction_.mu() * c.normal_impulse;
  }
}

double ExactSurfaceContact::relax(Contact& c, KinematicState& state) const {
  const int np = state.node[c.p], n0 = state.node[c.e0], n1 = state.node[c.e1];
  const double t = c.t, s = 1.0 - t;
  const Point tangent(-c.normal.y(), c.normal.x());
  auto push = [&](double impulse, const Point& direction, bool normal) {
    const Point j = impulse * direction, none = Point::Zero();
    state.apply(np, normal ? j : none, normal ? none : j);
    state.apply(n0, normal ? Point(-s * j) : none, normal ? none : Point(-s * j));
    state.apply(n1, normal ? Point(-t * j) : none, normal ? none : Point(-t * j));
  };
  // Normal: the depth still predicted along the contact's normal, less what was inside before.
  const Point q = s * state.predicted(c.e0) + t * state.predicted(c.e1);
  const double depth = c.normal.dot(q - state.predicted(c.p)) - c.inside;
  const double open = c.normal_impulse > 0.0 ? std::abs(depth) : std::max(depth, 0.0);
  const double normal = std::max(c.normal_impulse + depth / (state.dt * c.w), 0.0);
  const double dn = normal - c.normal_impulse;
  c.normal_impulse = normal;
  push(dn, c.normal, true);
  if (!friction_.active()) return open;
  // Friction: stop the predicted sliding, within mu times the normal impulse.
  const Point relative = state.velocity[np] - s * state.velocity[n0] - t * state.velocity[n1];
  const double limit = friction_.mu() * c.normal_impulse;
  const double tangential =
      std::clamp(c.friction_impulse - relative.dot(tangent) / c.w, -limit, limit);
  const double slide = tangential - c.friction_impulse;
  c.friction_impulse = tangential;
  push(slide, tangent, false);
  // Sticking: how far the predicted sliding it removed would have carried the pair.
  return std::max(open, std::abs(slide) * c.w * state.dt);
}

void ExactSurfaceContact::archive(StateArchive& a) {
  KinematicContactLaw::archive(a);
  search_.archive(a);
  a.vector("exact_cells.contacts", contacts_);
  a.value("exact_cells.sweeps", sweeps_);
}

}  // namespace vorodg
