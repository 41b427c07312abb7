#pragma once
// The work done on the mesh by the contact forces, booked step by step with the trapezoid rule,
//   W += (f_n + f_n+1) / 2 . (x_n+1 - x_n),   summed over the (cell, vertex) pairs,
// the way an explicit code books external work. A node's force is the sum of its pairs' and its
// pairs share its position, so the sum over pairs is the sum over nodes. With central
// differences x_n+1 - x_n = dt v_n+1/2, the half-step velocity that moved the pair, and this
// account is exact: summed by parts it is sum_n f_n . dt (v_n+1/2 + v_n-1/2) / 2, which is
// exactly the change that f makes in the half-step kinetic energy (m/2 |v_n+1/2|^2 -
// m/2 |v_n-1/2|^2), up to end terms that vanish out of contact. So
//   kinetic + strain - (external work) - ContactWork::work() = constant
// to the integrator's own accuracy, with no error from the penalty law. ContactReport's potential
// and dissipation say how W splits into stored and dissipated energy.
//
// Sparse: contact touches few pairs, so a step is booked over the pairs that carried a force at
// its start and those that carry one at its end, (f_n . dt v + f_n+1 . dt v) / 2 in two sums,
// and nothing is copied for the others (the full pass over every pair was 6 % of a column run).
#include <span>
#include <utility>
#include <vector>

#include "core/geometry/Rectangle.hpp"

namespace vorodg {

class StateArchive;

class ContactWork {
 public:
  /// Books the step that ends with the contact forces f at the pairs `support` (f is zero at
  /// every other pair), over which every pair moved by dt times its entry of `velocity`. The
  /// first call of an account only records. Throws InputError if f and velocity differ in size
  /// or a support index is out of range.
  void add(std::span<const Point> f, std::span<const int> support, std::span<const Point> velocity,
           double dt);
  /// The work done so far (negative while contact stores or dissipates energy).
  double work() const { return work_; }

  /// Saves or loads the account (a checkpoint).
  void archive(StateArchive& a);

 private:
  std::vector<std::pair<int, Point>> last_;  // the forces at the end of the last step
  double work_ = 0.0;
  bool started_ = false;
};

/// A ContactWork over several segments: the state may jump between them (a start, a remap), so
/// each segment starts its own trapezoid, and the work of the finished ones is kept.
class SegmentedWork {
 public:
  void add(std::span<const Point> f, std::span<const int> support, std::span<const Point> velocity,
           double dt) {
    current_.add(f, support, velocity, dt);
  }
  /// The next add starts a new segment (it only records).
  void restart() {
    booked_ += current_.work();
    current_ = ContactWork{};
  }
  double work() const { return booked_ + current_.work(); }

  void archive(StateArchive& a);

 private:
  ContactWork current_;
  double booked_ = 0.0;
};

}  // namespace vorodg
