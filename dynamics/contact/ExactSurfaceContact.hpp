#pragma once
// Contact between surface cells enforced exactly (ContactLaw::kinematic), with no parameter that
// depends on the step: a pairwise decomposition contact response in forward-increment form
// (after Cirak and West 2005; Carpenter, Taylor and Katona 1991). The surface cells' predicted
// next positions x' (KinematicState) are searched like the penalty law's current ones
// (SurfaceSearch, then vertex-in-polygon both ways); for a vertex p predicted inside cell b,
// with q' = (1 - t) e0' + t e1' the closest point of b's exit edge and n the normal out of b,
// one normal impulse lambda n on p and -lambda n split (1 - t, t) over e0 and e1 closes the
// predicted depth d':
//   lambda = (d' / dt) / w,   w = 1/m_p + (1 - t)^2 / m_e0 + t^2 / m_e1,
// so p lands on b's edge and the pair's relative normal approach is gone: a plastic impact,
// as the report's velocity penalty intended, but without its k_v = m / dt. The impulses are
// equal and opposite, so momentum is conserved to round-off, and their moment vanishes to first
// order (they act along n through q). Coulomb friction is the tangential impulse that would stop
// the pair's predicted sliding, capped by mu lambda.
//
// Why this choice and not a penalty from the cells' impedance: a penalty needs a stiffness, and
// any stiffness either sets the stable step (stiff) or lets a vertex sink (soft); the report's
// column showed that the sink is what the corner's crushing depends on. The impulse has nothing
// to choose, conserves momentum exactly, and its limit dt -> 0 is the constraint itself. Its
// costs: the contacts of a step are coupled where they share nodes, so their impulses are found
// together by projected Gauss-Seidel (normal impulses >= 0, friction within mu of them) until the
// predictions stop moving; and it is a node-to-edge response, so two edges crossing with no
// vertex inside (PolygonPenetration's limits) are missed, and a vertex sliding exactly along
// the line of the other cell's boundary is never inside it.
//
// What was inside before: a vertex already behind b's edge at the current positions (a contact
// found late, its target a new surface cell after a crack, or left there by another law) is not
// pushed out, which would make kinetic energy from nothing; only its further approach is stopped
// (the law acts on d' - d, d the current depth along the same normal to the same point of the
// edge, so that d' - d is the step's approach and nothing more). The exit edges of a cell are its
// exposed ones (SurfaceCells), so a vertex that enters b across a bonded edge is found at a
// depth up to a good part of b, measured to b's far, exposed side, while at the current
// positions it is not inside b at all: closing that depth in one step flung it out at d' / dt
// (measured on the column: contacts that made 30 times the input energy at a quarter step). A
// vertex first predicted deeper than SurfaceSearch::kTunnelDepth of b's size tunnelled in and is
// left alone (`tunnelled` in the report).
#include <cstdint>
#include <span>
#include <unordered_set>
#include <vector>

#include "dynamics/contact/ContactFriction.hpp"
#include "dynamics/contact/ContactLaw.hpp"
#include "dynamics/contact/PolygonPenetration.hpp"
#include "dynamics/contact/SurfaceSearch.hpp"

namespace vorodg {

class StateArchive;

class ExactSurfaceContact final : public KinematicContactLaw {
 public:
  /// grid_spacing > 0: the search grid's smallest spacing (the mesh's h_avg).
  explicit ExactSurfaceContact(double grid_spacing,
                               const ContactFriction& friction = ContactFriction{});

  bool external() const override { return false; }
  ContactReport constrain(const SurfaceCells& surface, KinematicState& state) override;

  /// The projected Gauss-Seidel sweeps the last constrain() took.
  int sweeps() const { return sweeps_; }

  /// The sweeps stop when no contact is left open by more than this fraction of the grid
  /// spacing, or after kMaxSweeps.
  static constexpr double kTolerance = 1e-9;
  static constexpr int kMaxSweeps = 100;

  void archive(StateArchive& a) override;

 private:
  /// One vertex-to-edge contact at the predicted positions, with its accumulated impulses.
  struct Contact {
    int p = -1, e0 = -1, e1 = -1;  // the vertex's pair, the edge's ends' pairs
    double t = 0.0;                // q = (1 - t) e0 + t e1
    Point normal = Point::Zero();  // out of the target cell
    double inside = 0.0;           // the depth along `normal` at the current positions (kept)
    double w = 0.0;                // 1/m_p + (1 - t)^2 / m_e0 + t^2 / m_e1
    double normal_impulse = 0.0, friction_impulse = 0.0;
  };
  /// The contacts of surface cell i's vertices with surface cell j (surface order).
  void find_contacts(const SurfaceCells& surface, int i, int j, const KinematicState& state,
                     ContactReport& report);
  /// The impulses of every contact found (projected Gauss-Seidel), applied to `state`.
  void solve(KinematicState& state, ContactReport& report);
  /// One contact's update within a sweep; returns how far it was open before it (its depth,
  /// or its gap while it pushes; with friction, also the slip it stopped).
  double relax(Contact& c, KinematicState& state) const;

  ContactFriction friction_;
  SurfaceSearch search_;
  double spacing_;
  std::vector<Point> predicted_;             // per pair: x' (surface cells' pairs only)
  std::unordered_set<std::uint64_t> taken_;  // (node, target cell) keys of this evaluation
  std::vector<Contact> contacts_;
  int sweeps_ = 0;
};

}  // namespace vorodg
