#pragma once
// What a kinematic contact law (ContactLaw::kinematic) reads and changes: the contact enforced
// exactly, as a constraint on the next configuration, instead of by a force of the current one.
//
// Forward-increment form (Carpenter, Taylor and Katona 1991): when every other force of the
// step is known, each free node's next half-step velocity follows, v' = w + beta dt a (central
// differences: w = v_{n+1/2}, beta = 1; at a start or restart w = v_n, beta = 1/2), and with it
// the next position x' = x + dt v'. A kinematic law looks at those predicted positions; where a
// node would end up behind an obstacle or inside another cell, it applies momentum impulses J
// (per node) that change v' by J / m, so that x' lands exactly on the surface and the normal
// approach is gone (a plastic impact of the node, as the report asks; the body still rebounds
// by its own elastic waves). The integrator turns the impulses into the forces of the current
// step, f = (1 + c dt / 2) J / (beta dt) with mass damping c, so that they enter the
// accelerations, the momenta and the work account like any other force. Nothing in it
// depends on the step but the step's own kinematics: the limit dt -> 0 is the exact constraint.
//
// A law applies its impulses through apply(), each on the predictions the earlier ones left:
// ExactSurfaceContact iterates over its contacts until they agree (projected Gauss-Seidel), and
// the laws act one after the other in the order they were added (the plane after the cells, so
// that what it leaves is exact for it; what a later law moves is resolved at the next step).
// Per contact the impulses are equal and opposite (or taken by an obstacle), so momentum is
// conserved to round-off.
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "core/geometry/Rectangle.hpp"

namespace vorodg {

struct KinematicState {
  /// Current position x = X + u of each (cell, vertex) pair, in the mesh's CSR layout.
  std::span<const Point> position;
  /// Node of each pair.
  std::span<const int> node;
  /// Per node: the predicted next half-step velocity v', updated by every impulse applied.
  /// Read only at the nodes of surface cells.
  std::span<Point> velocity;
  /// Per node: 1 / m, zero for a node the loads hold (a prescribed velocity): it takes no
  /// impulse, and a contact against it is resolved by the other side alone.
  std::span<const double> inverse_mass;
  /// Per node: the normal (contact-closing) and the tangential (friction) impulses applied,
  /// added to.
  std::span<Point> normal_impulse, friction_impulse;
  double dt = 0.0;

  Point predicted(int pair) const { return position[pair] + dt * velocity[node[pair]]; }
  /// The largest predicted speed |v'| over the nodes: no predicted position is farther than
  /// dt times it from the current one, which lets a law pass over the far pairs unread.
  /// Infinite if a velocity is not finite, so that nothing is passed over and the law meets it.
  double max_speed() const {
    double squared = 0.0;
    for (const Point& v : velocity) {
      const double s = v.squaredNorm();
      if (!std::isfinite(s)) return std::numeric_limits<double>::infinity();
      squared = std::max(squared, s);
    }
    return std::sqrt(squared);
  }
  /// Applies the impulse j (normal part jn, friction part jt, j = jn + jt) to node i.
  void apply(int i, const Point& jn, const Point& jt) {
    const double w = inverse_mass[i];
    if (w == 0.0) return;
    velocity[i] += w * (jn + jt);
    normal_impulse[i] += jn;
    friction_impulse[i] += jt;
  }
};

}  // namespace vorodg
