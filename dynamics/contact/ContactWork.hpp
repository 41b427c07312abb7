#pragma once
// The work done on the mesh by the contact forces, booked step by step with the trapezoid rule,
//   W += (f_n + f_n+1) / 2 . (x_n+1 - x_n),   summed over the (cell, vertex) pairs,
// the way an explicit code books external work. A node's force is the sum of its pairs' and its
// pairs share its position, so the sum over pairs is the sum over nodes. With central
// differences this account is exact: summed by parts it is sum_n f_n . (x_n+1 - x_n-1) / 2, which
// is exactly the change that f makes in the half-step kinetic energy (m/2 |v_n+1/2|^2 -
// m/2 |v_n-1/2|^2 = f_n . (x_n+1 - x_n-1) / 2), up to end terms that vanish out of contact. So
//   kinetic + strain - (external work) - ContactWork::work() = constant
// to the integrator's own accuracy, with no error from the penalty law. ContactReport's potential
// and dissipation say how W splits into stored and dissipated energy.
#include <span>
#include <vector>

#include "core/geometry/Rectangle.hpp"

namespace vorodg {

class ContactWork {
 public:
  /// Books the step that ends at positions x, where the contact forces are f (one entry per
  /// pair, e.g. SurfaceContact and RigidPlane forces added together). The first call only
  /// records. Throws InputError if the sizes differ from each other or from the last call.
  void add(std::span<const Point> x, std::span<const Point> f);
  /// The work done so far (negative while contact stores or dissipates energy).
  double work() const { return work_; }

 private:
  std::vector<Point> x_, f_;
  double work_ = 0.0;
  bool started_ = false;
};

}  // namespace vorodg
