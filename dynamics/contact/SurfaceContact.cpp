#include "dynamics/contact/SurfaceContact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/io/StateArchive.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

/// One 64-bit key for (a pair or a node, a target cell).
std::uint64_t key_of(int who, int cell) {
  return (static_cast<std::uint64_t>(who) << 32) | static_cast<std::uint32_t>(cell);
}

}  // namespace

SurfaceContact::SurfaceContact(const PenaltyContact& law, double grid_spacing,
                               const ContactFriction& friction)
    : law_(law), friction_(friction), search_(grid_spacing) {}

ContactReport SurfaceContact::add_forces(const SurfaceCells& surface, const PairState& state,
                                         std::span<Point> force, std::span<Point> velocity_force) {
  check_pair_state(surface.mesh(), state, "surface contact");
  law_.check(state, "surface contact");
  if (force.size() != state.position.size())
    throw InputError("surface contact: " + std::to_string(force.size()) +
                     " force entries: expected one per (cell, vertex) pair, " +
                     std::to_string(state.position.size()));
  search_.find(surface, state.position);
  taken_.clear();
  touched_.clear();
  ContactReport report;
  report.candidates = static_cast<int>(search_.surface_pairs().size());
  inside_next_.clear();
  tunnelled_next_.clear();
  for (const IndexPair& ij : search_.surface_pairs()) {
    test_pass(surface, ij.first, ij.second, state, force, velocity_force, report);
    test_pass(surface, ij.second, ij.first, state, force, velocity_force, report);
  }
  std::swap(inside_, inside_next_);
  std::swap(tunnelled_, tunnelled_next_);
  return report;
}

std::optional<SurfaceContact::Acting> SurfaceContact::acting_depth(std::uint64_t key, double depth,
                                                                   double reach,
                                                                   const PolygonMesh& mesh, int b,
                                                                   ContactReport& report) {
  const bool known_tunnel = tunnelled_.count(key) != 0;
  if (!known_tunnel) {
    double offset = 0.0, shear = 0.0;
    if (const auto known = inside_.find(key); known != inside_.end()) {
      offset = std::min(known->second.offset, depth);  // the least depth seen
      shear = known->second.shear;
    } else if (depth <= SurfaceSearch::kTunnelDepth * std::sqrt(mesh.cell_area(b))) {
      offset = std::max(depth - reach, 0.0);
      report.new_late += offset > 0.0;
    } else {
      offset = -1.0;  // tunnelled
    }
    if (offset >= 0.0) {
      inside_next_.emplace(key, Tracked{offset, 0.0});
      report.late += offset > 0.0;
      return Acting{depth - offset, shear};
    }
  }
  tunnelled_next_.insert(key);
  ++report.tunnelled;
  report.new_tunnels += !known_tunnel;
  return std::nullopt;
}

void SurfaceContact::test_pass(const SurfaceCells& surface, int i, int j, const PairState& state,
                               std::span<Point> force, std::span<Point> velocity_force,
                               ContactReport& report) {
  const PolygonMesh& mesh = surface.mesh();
  const int a = surface.cells()[i], b = surface.cells()[j];
  const int base_a = mesh.offsets()[a], base_b = mesh.offsets()[b], nb = mesh.cell_size(b);
  const auto loop_a = SurfaceSearch::loop(mesh, state.position, a);
  const auto loop_b = SurfaceSearch::loop(mesh, state.position, b);
  const auto exits =
      surface.has_exposed_edge(b) ? surface.exposed_edges(b) : std::span<const char>{};
  const Box& box_b = search_.box(j);
  for (std::size_t k = 0; k < loop_a.size(); ++k) {
    if (!box_b.contains(loop_a[k])) continue;  // cheap test first: most candidates never touch
    const auto pen = PolygonPenetration::of_point(loop_a[k], loop_b, exits);
    if (!pen) continue;
    const int p = base_a + static_cast<int>(k);
    const int e0 = base_b + pen->edge, e1 = base_b + (pen->edge + 1) % nb;
    const double reach =
        state.velocity.empty()
            ? std::numeric_limits<double>::infinity()
            : kReachSlack * state.dt *
                  std::max(PenaltyContact::approach_rate(*pen, p, e0, e1, state), 0.0);
    const auto depth = acting_depth(key_of(p, b), pen->depth, reach, mesh, b, report);
    if (!depth) continue;
    if (!taken_.insert(key_of(state.node_of(p), b)).second)
      continue;  // this node is already pushed out of b
    Penetration acting = *pen;
    acting.depth = depth->depth;
    const auto r = law_.apply(acting, p, e0, e1, state, force, velocity_force);
    touched_.insert(touched_.end(), {p, e0, e1});
    if (friction_.active())
      add_friction(key_of(p, b), acting, p, e0, e1, r, depth->shear, state, force, report);
    ++report.contacts;
    report.potential += r.potential;
    report.dissipation_power += r.dissipation_power;
    report.max_depth = std::max(report.max_depth, pen->depth);
  }
}

void SurfaceContact::add_friction(std::uint64_t key, const Penetration& pen, int p, int e0, int e1,
                                  const PenaltyContact::Response& normal, double previous_shear,
                                  const PairState& state, std::span<Point> force,
                                  ContactReport& report) {
  double shear = previous_shear;
  const Point f =
      friction_.force(pen.normal, PenaltyContact::relative_velocity(pen, p, e0, e1, state), normal,
                      state, shear, report, "surface contact");
  PenaltyContact::distribute(f, pen.t, p, e0, e1, force);
  inside_next_[key].shear = shear;
}

void SurfaceContact::archive(StateArchive& a) {
  search_.archive(a);
  a.vector("penalty_cells.touched", touched_);
  a.map("penalty_cells.inside", inside_);
  a.set("penalty_cells.tunnelled", tunnelled_);
}

}  // namespace vorodg
