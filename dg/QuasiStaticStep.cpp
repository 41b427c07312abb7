// QuasiStaticPath, second half: what one load step does (docs/fracture.md "Path following"):
// the step's target in the control's measure, the location of an insertion inside the step,
// the insertion and settling of the failed points, and the energy-balance check that halves
// a step which crosses a kink of the law too coarsely.
#include <algorithm>
#include <cmath>

#include "dg/QuasiStaticPath.hpp"

namespace vorodg {

/// The next target in the control's own measure (stroke or cmod) from `at`: a step of the stage
/// `at` is in (the main stage up to `main_end`, then the tail), never past the stage's end.
double QuasiStaticPath::staged_target(double at, double main_end, double fraction) const {
  const bool in_tail = options_.tail_steps > 0 && at >= (1.0 - 1e-12) * main_end;
  const double begin = in_tail ? main_end : 0.0, end = in_tail ? options_.tail_end : main_end;
  const int steps = in_tail ? options_.tail_steps : options_.steps;
  return std::min(at + fraction * (end - begin) / steps, end);
}

QuasiStaticPath::Target QuasiStaticPath::step_target(const State& start, LoadControl control,
                                                     double fraction) const {
  const double unit = model_.stroke(1.0);
  switch (control) {
    case LoadControl::displacement:
      if (options_.control != LoadControl::displacement)  // the elastic phase of cmod, arc-length
        return {control, start.lambda + fraction * elastic_step_};
      return {control,
              staged_target(model_.stroke(start.lambda), options_.max_stroke, fraction) / unit};
    case LoadControl::cmod:
      return {control, staged_target(cmod(start), options_.max_cmod, fraction)};
    case LoadControl::arc_length: break;
  }
  return {control, fraction * arc_};
}

double QuasiStaticPath::max_utilization(const State& s, const Eigen::VectorXd& u) const {
  double most = 0.0;
  for (int p : model_.eligible_points(s.points))
    most = std::max(most, model_.interfaces().utilization(u, p));
  return most;
}

bool QuasiStaticPath::softened(const State& s) const {
  const CohesiveInterfaces& faces = model_.interfaces();
  for (int p = 0; p < static_cast<int>(s.points.size()); ++p) {
    const InterfacePoint& point = s.points[p];
    if ((point.state == PointState::cohesive && !faces.law(p).intrinsic()) ||
        faces.law(p).dissipated_energy(point.history.max_opening) > 0.0)
      return true;
  }
  return false;
}

bool QuasiStaticPath::finished(const State& s) const {
  const double stroke = model_.stroke(s.lambda), c = cmod(s);
  const double close = 1.0 - 1e-12;
  switch (options_.control) {
    case LoadControl::displacement:
      return stroke >= close * (options_.tail_steps > 0 ? options_.tail_end : options_.max_stroke);
    case LoadControl::cmod:
      return c >= close * (options_.tail_steps > 0 ? options_.tail_end : options_.max_cmod);
    case LoadControl::arc_length: break;
  }
  return (options_.max_stroke > 0.0 && stroke >= close * options_.max_stroke) ||
         (options_.max_cmod > 0.0 && c >= close * options_.max_cmod);
}

PathPoint QuasiStaticPath::point_of(const State& s, int step, const PathPoint& previous) const {
  PathPoint p;
  p.step = step;
  p.stroke = model_.stroke(s.lambda);
  p.cmod = cmod(s);
  p.load = model_.load(s.force) / model_.stroke(1.0);
  // The machine's work: trapezoids in the stroke (exact on every linear stretch of the path).
  // The stretch ends at the load on arrival: settling after an insertion does no work.
  const double arrival = std::isnan(s.arrival_load) ? p.load : s.arrival_load;
  p.external_work =
      previous.external_work + 0.5 * (previous.load + arrival) * (p.stroke - previous.stroke);
  p.energy = model_.energies(full(s), s.points);
  p.energy.switched = switched_;
  return p;
}

/// Turns the eligible intact points at or past the criterion cohesive, books the jump in the
/// accounted energy that switching their terms makes, and settles the body at the same stroke:
/// the face law starts from sigma_c n, without the shear or the excess the point carried, so the
/// body is out of balance after the switch. Settling does no external work; the energy it
/// releases (what a dynamic code would lose to kinetic energy and damping) is booked with the
/// switch. Points that the settling fails in turn are inserted too, until none is left.
int QuasiStaticPath::insert_failed_points(State& trial) {
  if (model_.setup().mode == CrackingMode::pre_inserted) return 0;
  int inserted = 0;
  for (int round = 0; round < kSettlingRounds; ++round) {
    const Eigen::VectorXd u = full(trial);
    const double before = model_.energies(u, trial.points).accounted();
    int now = 0;
    for (int p : model_.eligible_points(trial.points))
      if (model_.interfaces().utilization(u, p) >= 1.0) {
        trial.points[p].state = PointState::cohesive;
        trial.points[p].offset = model_.interfaces().opening(u, p);
        ++now;
      }
    if (now == 0) break;
    if (inserted == 0) trial.arrival_load = model_.load(trial.force) / model_.stroke(1.0);
    inserted += now;
    State settled;
    int its = 0;
    if (!newton(trial, {LoadControl::displacement, trial.lambda, kSettlingIterations}, settled,
                its)) {
      model_.forces(u, trial.points, nullptr);  // the switched points' law takes up their opening
      switched_ += before - model_.energies(u, trial.points).accounted();
      break;  // the next step's Newton will have to settle it
    }
    switched_ += before - model_.energies(full(settled), settled.points).accounted();
    settled.arrival_load = trial.arrival_load;
    trial = std::move(settled);
  }
  return inserted;
}

/// How much the step widens the energy balance's gap (the trapezoids of the external work against
/// the accounted energy): the gap after it less the gap before, and the gap after it over the work.
QuasiStaticPath::BalanceDrift QuasiStaticPath::balance_drift(const State& trial) const {
  const PathPoint after = point_of(trial, 0, last_);
  const double gap = std::abs(after.external_work - after.energy.accounted());
  const double before = std::abs(last_.external_work - last_.energy.accounted());
  return {gap - before, gap / std::max(after.external_work, 1e-300)};
}

/// The energy a jump is measured against: the larger of the work so far and the fracture energy
/// of a crack across the whole body (G x height x thickness), so that a small slip early on,
/// when little work has been done, is not mistaken for one.
double QuasiStaticPath::jump_scale(const State& trial) const {
  return std::max(point_of(trial, 0, last_).external_work, crack_energy());
}

double QuasiStaticPath::crack_energy() const {
  return model_.interfaces().law().parameters().fracture_energy *
         model_.space().mesh().domain().height() * model_.setup().thickness;
}

/// How far past the next insertion a trial state is: the largest Mohr-Coulomb utilization of the
/// eligible intact points, less one (negative: no event yet). Kinks of the law (the peak, the
/// bilinear kink, delta_c) and contact or unloading switches are not located: the energy-balance
/// check shortens the steps that cross them badly, which costs far fewer solves than locating
/// every kink of every point.
double QuasiStaticPath::event_excess(const State& trial) const {
  if (model_.setup().mode == CrackingMode::pre_inserted) return -1.0;
  return max_utilization(trial, full(trial)) - 1.0;
}

/// Until something softens, every face law is positively homogeneous of degree one (the intrinsic
/// branch K0 in tension, the closure penalty in compression), so the response to any load is the
/// elastic probe's scaled. It is piecewise linear, though: faces near the neutral axis switch
/// between the two branches, and Newton can cycle between such sets of branches (a notched beam's
/// first step failed so in 20 of 2896 runs of a campaign, the residual stalling near 1e-2). A cut
/// cannot help, since a smaller step is the same cycle scaled. The probe, solved at a tiny load,
/// knows the branches; scaled to the target it is the answer, and Newton from there confirms it.
/// Tried only once a step has failed at every cut, so every path that converged is unchanged.
bool QuasiStaticPath::newton_from_probe(const State& state, const Target& target, State& out,
                                        int& iterations) {
  if (probe_.x.size() == 0 || softened(state)) return false;
  double reached = 0.0;  // the probe's value of the controlled quantity
  if (target.control == LoadControl::displacement) reached = probe_.lambda;
  if (target.control == LoadControl::cmod) reached = cmod(probe_);
  if (!(std::abs(reached) > 0.0)) return false;  // arc length, or a silent gauge
  State origin;
  origin.x = Eigen::VectorXd::Zero(probe_.x.size());
  int its = 0;
  const bool converged =
      newton(state, target, out, its, Guess{&origin, &probe_, target.value / reached});
  iterations += its;
  return converged;
}

/// One step from `state`: Newton to the step's target (halved on failure); if an insertion falls
/// inside the step, the step is shortened to it, and the failed points are inserted there.
bool QuasiStaticPath::take_step(State& state, int& iterations, int& inserted) {
  if (try_step(state, iterations, inserted, false)) return true;
  return options_.restart_from_probe && !jumped_ && !softened(state) && probe_.x.size() > 0 &&
         try_step(state, iterations, inserted, true);
}

bool QuasiStaticPath::try_step(State& state, int& iterations, int& inserted, bool from_probe) {
  const bool elastic_phase =
      options_.control != LoadControl::displacement && !softened(state) && elastic_step_ > 0.0;
  const LoadControl control = elastic_phase ? LoadControl::displacement : options_.control;
  const double tol = options_.event_tolerance;
  double fraction = 1.0, previous_widening = 0.0;
  for (int cut = 0; cut <= options_.max_cuts; ++cut, fraction *= 0.5) {
    State trial;
    const Target target = step_target(state, control, fraction);
    if (!(from_probe ? newton_from_probe(state, target, trial, iterations)
                     : newton(state, target, trial, iterations)))
      continue;
    double excess = event_excess(trial);
    if (excess > tol) {
      // Regula falsi (Illinois) on the step fraction for the excess to land in [0, tol], with a
      // bisection whenever a secant step fails to halve the bracket (the excess can be flat for
      // most of the step and steep at its end). Each trial starts from the interpolation of the
      // bracketing states: exact where the stretch is linear, so Newton has little left to do.
      double lo = 0.0, e_lo = std::min(event_excess(state), 0.0), hi = fraction, e_hi = excess;
      State lo_state = state, hi_state = trial;
      int side = 0;
      bool ok = true, bisect = false;
      for (int k = 0; k < kEventSearches && (excess < 0.0 || excess > tol); ++k) {
        const double width = hi - lo;
        const double s = bisect || !std::isfinite(e_hi)
                             ? lo + 0.5 * width
                             : std::clamp(lo + (0.5 * tol - e_lo) / (e_hi - e_lo) * width,
                                          lo + 1e-9 * width, hi - 1e-9 * width);
        int its = 0;
        const Guess guess{&lo_state, &hi_state, (s - lo) / width};
        if (!(ok = newton(state, step_target(state, control, s), trial, its, guess))) break;
        iterations += its;
        excess = event_excess(trial);
        if (excess < 0.0) {
          lo = s, e_lo = excess, lo_state = trial;
          if (side == -1) e_hi *= 0.5;
          side = -1;
        } else {
          hi = s, e_hi = excess, hi_state = trial;
          if (side == 1) e_lo *= 0.5;
          side = 1;
        }
        bisect = !bisect && hi - lo > 0.5 * width;
      }
      if (!ok || excess < 0.0) continue;
    }
    const double switched_before = switched_;
    inserted = insert_failed_points(trial);
    // The step is kept if, after it, the balance holds within balance_tolerance of the work, or
    // the step does not widen the gap. Else it is halved, down to 1/64, while halving helps. A
    // kink at a fraction theta of the step costs the trapezoids theta (1 - theta) of the step
    // squared; halving leaves (1 - 2 theta) / (2 (1 - theta)) of it, just under half at theta ->
    // 0 (a face opening right after an insertion), so the bound sits above half with a margin
    // for round-off; a smooth stretch leaves an eighth. A widening that halving leaves above
    // kHalvingHelps of itself does not depend on the step (a jump), and cutting further would
    // only multiply the solves.
    const BalanceDrift drift = balance_drift(trial);
    const bool kept = drift.relative_gap <= options_.balance_tolerance || drift.widening <= 0.0;
    const bool halving_helped =
        !(previous_widening > 0.0) || drift.widening < kHalvingHelps * previous_widening;
    if (!kept && halving_helped && fraction > kSmallestBalancedStep) {
      switched_ = switched_before;
      previous_widening = drift.widening;
      continue;
    }
    if (!kept && drift.widening > kJumpLimit * jump_scale(trial)) {
      switched_ = switched_before;
      jumped_ = true;
      return false;
    }
    state = std::move(trial);
    return true;
  }
  return false;
}

}  // namespace vorodg
