#pragma once
// A rigid, fixed half-plane {x : (x - point) . n < 0} that surface cells may not enter (a floor, a
// wall, an anvil), with the same penalty law as cell-to-cell contact. A vertex with gap
// g = (x - point) . n < 0 penetrates by d = -g and is pushed along n; the plane takes the
// reaction, so these forces are external to the mesh and do work on it. The target is rigid, so
// the law's reduced mass is the vertex's own mass.
//
// The plane has its own Coulomb friction (ContactFriction; 0 by default): a contacting vertex
// carries its shear along the plane from step to step, keyed by its pair.
#include <span>
#include <unordered_map>
#include <vector>

#include "dynamics/contact/ContactFriction.hpp"
#include "dynamics/contact/ContactLaw.hpp"
#include "dynamics/contact/ContactReport.hpp"
#include "dynamics/contact/HalfPlane.hpp"
#include "dynamics/contact/PairState.hpp"
#include "dynamics/contact/PenaltyContact.hpp"
#include "dynamics/contact/SurfaceCells.hpp"

namespace vorodg {

class StateArchive;

class RigidPlane final : public ContactLaw {
 public:
  /// `normal` points out of the plane's solid side, into the free space; it is normalized.
  /// Throws InputError for a zero or non-finite normal, or a non-finite point.
  RigidPlane(const Point& point, const Point& normal, const PenaltyContact& law,
             const ContactFriction& friction = ContactFriction{});

  const Point& point() const { return plane_.point; }
  const Point& normal() const { return plane_.normal; }
  const ContactFriction& friction() const { return friction_; }
  /// Signed distance from the plane, negative inside the solid.
  double gap(const Point& x) const { return plane_.gap(x); }

  /// Adds the plane's forces on the vertices of surface cells to `force` (one entry per pair;
  /// each node counted once, on its first pair in surface order), their velocity penalty's part
  /// to `velocity_force` if it is not empty, and reports the step.
  ContactReport add_forces(const SurfaceCells& surface, const PairState& state,
                           std::span<Point> force, std::span<Point> velocity_force = {}) override;
  /// The pairs the last add_forces gave a force, in the order it did.
  std::span<const int> touched() const override { return touched_; }
  /// The plane takes the reaction.
  bool external() const override { return true; }

  void archive(StateArchive& a) override;

 private:
  /// Friction on pair p, pushed by `normal` of stiffness k: adds the shear along the plane.
  void add_friction(int p, const PenaltyContact::Response& normal, const PairState& state,
                    std::span<Point> force, ContactReport& report);

  HalfPlane plane_;
  PenaltyContact law_;
  ContactFriction friction_;
  // The shear of each contacting pair at the last evaluation and at this one.
  std::unordered_map<int, double> shear_, shear_next_;
  std::vector<int> touched_;
};

}  // namespace vorodg
