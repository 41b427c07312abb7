#pragma once
// A fixed rigid half-plane {x : (x - point) . n < 0} enforced exactly (ContactLaw::kinematic): a
// node whose predicted next position x' lies behind the plane gets the normal impulse that puts
// it back on it, J_n = m (-g') / dt n with g' = (x' - point) . n, which also removes its normal
// velocity into the plane (a plastic impact of the node; the body rebounds by its own waves).
// Coulomb friction is an impulse too: the one that would stop the node's predicted sliding along
// the plane, capped by mu |J_n|. The plane takes the reactions (external).
//
// No parameter depends on the step: as dt -> 0 the law tends to the exact unilateral
// constraint, so what a run measures converges with the step. Compare RigidPlane, the penalty
// plane of the report (Heinstein et al.), whose velocity penalty k_v = m / dt makes its force a
// one-step impulse and lets through a share R / (1 + R) of the impact stress, R = m / (dt rho c l).
#include <span>
#include <vector>

#include "dynamics/contact/ContactFriction.hpp"
#include "dynamics/contact/ContactLaw.hpp"
#include "dynamics/contact/HalfPlane.hpp"

namespace vorodg {

class StateArchive;

class ExactPlane final : public KinematicContactLaw {
 public:
  /// `normal` points out of the plane's solid side, into free space; it is normalized. Throws
  /// InputError for a zero or non-finite normal, or a non-finite point.
  ExactPlane(const Point& point, const Point& normal,
             const ContactFriction& friction = ContactFriction{});

  const Point& point() const { return plane_.point; }
  const Point& normal() const { return plane_.normal; }
  double gap(const Point& x) const { return plane_.gap(x); }

  bool external() const override { return true; }
  ContactReport constrain(const SurfaceCells& surface, KinematicState& state) override;

  void archive(StateArchive& a) override;

 private:
  HalfPlane plane_;
  ContactFriction friction_;
  std::vector<long> seen_;  // per node: the evaluation that last met it (each node once)
  long evaluation_ = 0;
};

}  // namespace vorodg
