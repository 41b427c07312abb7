#include "dg/QuasiStaticPath.hpp"

#include <algorithm>
#include <cmath>

#include "core/util/Errors.hpp"

namespace vorodg {

LoadControl parse_load_control(const std::string& name) {
  for (LoadControl c : {LoadControl::displacement, LoadControl::cmod, LoadControl::arc_length})
    if (load_control_name(c) == name) return c;
  throw InputError("load control '" + name + "': expected displacement, cmod or arc-length");
}

std::string load_control_name(LoadControl control) {
  switch (control) {
    case LoadControl::displacement: return "displacement";
    case LoadControl::cmod: return "cmod";
    case LoadControl::arc_length: break;
  }
  return "arc-length";
}

double PathPoint::balance_error() const {
  if (!(external_work > 0.0)) return 0.0;
  return std::abs(external_work - energy.accounted()) / external_work;
}

QuasiStaticPath::QuasiStaticPath(const CohesiveFracture& model, const PathOptions& options)
    : model_(model), options_(options) {
  if (options.steps < 1) throw InputError("loading.steps: expected >= 1");
  const bool by_stroke = options.control == LoadControl::displacement;
  const bool by_cmod = options.control == LoadControl::cmod;
  if (by_stroke && !(options.max_stroke > 0.0))
    throw InputError("loading.max_displacement: expected > 0 with displacement control");
  if (by_cmod && !(options.max_cmod > 0.0))
    throw InputError("loading.max_cmod: expected > 0 with cmod control");
  if (by_cmod && model.mouth_gauge().squaredNorm() == 0.0)
    throw InputError("loading.control cmod: the crack mouth is not split on this mesh");
  if (options.control == LoadControl::arc_length &&
      !(options.max_stroke > 0.0 || options.max_cmod > 0.0))
    throw InputError("loading: arc-length control needs max_displacement or max_cmod > 0");
  if (options.tail_steps > 0) {
    const double main_end = by_cmod ? options.max_cmod : options.max_stroke;
    if (!by_stroke && !by_cmod)
      throw InputError("loading.tail: only with displacement or cmod control");
    if (!(options.tail_end > main_end))
      throw InputError("loading.tail: its end must lie beyond the main stage's end");
  }
  const PolygonMesh& mesh = model.space().mesh();
  const double side = std::min(mesh.domain().width(), mesh.domain().height());
  force_scale_ = model.interfaces().law().parameters().strength * side;
}

void QuasiStaticPath::factor(const Eigen::SparseMatrix<double>& tangent, Eigen::VectorXd& q) {
  const ProportionalConstraints& cons = model_.constraints();
  if (!free_lower_) {  // the tangent's pattern never changes: map it onto the free DOFs once
    std::vector<int> index(cons.num_dofs());
    for (int i = 0; i < cons.num_dofs(); ++i) index[i] = cons.free_index(i);
    free_lower_.emplace(tangent, index, cons.num_free());
  }
  const Eigen::SparseMatrix<double>& A = free_lower_->restrict(tangent);
  q = cons.restrict(tangent * cons.reference());  // dR / d lambda
  FactorizationOptions fo;
  fo.min_rcond = 0.0;  // near a limit point the tangent is nearly singular by nature
  for (;;) {
    fo.indefinite = indefinite_;
    fo.reuse_analysis = analysed_;
    try {
      solver_.factorize(A, fo);
      analysed_ = true;
      ++factorizations_;
      return;
    } catch (const NumericalError&) {
      if (indefinite_) throw;
      indefinite_ = true;  // softening made the tangent indefinite: LDL^T from now on
      analysed_ = false;
    }
  }
}

bool QuasiStaticPath::newton(const State& start, const Target& target, State& out, int& iterations,
                             const Guess& guess) {
  const ProportionalConstraints& cons = model_.constraints();
  const Eigen::VectorXd gauge_free = cons.restrict(model_.mouth_gauge());
  const double gauge_lambda = model_.mouth_gauge().dot(cons.reference());
  out.x = start.x;
  out.lambda = start.lambda;
  if (guess.from && guess.to) {  // between two converged states of a smooth stretch
    out.x = (1.0 - guess.weight) * guess.from->x + guess.weight * guess.to->x;
    out.lambda = (1.0 - guess.weight) * guess.from->lambda + guess.weight * guess.to->lambda;
  }
  const bool guessed = guess.from && guess.to;
  for (iterations = 0; iterations <= options_.max_iterations; ++iterations) {
    const Eigen::VectorXd u = full(out);
    out.points = start.points;
    Eigen::SparseMatrix<double> K;
    out.force = model_.forces(u, out.points, &K);
    const Eigen::VectorXd R = cons.restrict(out.force);
    double gap = 0.0;  // how far the extra equation is from holding
    switch (target.control) {
      case LoadControl::displacement: gap = std::abs(target.value - out.lambda); break;
      case LoadControl::cmod:
        gap = std::abs(target.value - model_.mouth_gauge().dot(u)) /
              std::max(std::abs(target.value), 1e-300);
        break;
      case LoadControl::arc_length:
        gap = std::abs((out.x - start.x).norm() - target.value) / target.value;
        break;
    }
    // Residual relative to the larger of the strength's force scale and the reactions (whose
    // round-off floor it shares).
    const double reactions = std::sqrt(std::max(out.force.squaredNorm() - R.squaredNorm(), 0.0));
    const double scale = std::max(force_scale_, reactions);
    if ((iterations > 0 || guessed) && R.norm() <= options_.tolerance * scale && gap <= 1e-9)
      return true;
    if (iterations == options_.max_iterations) return false;
    Eigen::VectorXd q;
    try {
      factor(K, q);
    } catch (const NumericalError&) {
      return false;
    }
    const Eigen::VectorXd a = solver_.solve(-R), b = solver_.solve(q);
    double dl = 0.0;
    if (target.control == LoadControl::displacement) {
      dl = target.value - out.lambda;
    } else if (target.control == LoadControl::cmod) {
      const double c = model_.mouth_gauge().dot(u);
      const double denominator = gauge_lambda - gauge_free.dot(b);
      if (denominator == 0.0) return false;
      dl = (target.value - c - gauge_free.dot(a)) / denominator;
    } else {  // |dx + a - dl b| = s: a quadratic in dl
      const Eigen::VectorXd v = out.x - start.x + a;
      const double A = b.squaredNorm(), B = -2.0 * b.dot(v),
                   C = v.squaredNorm() - target.value * target.value;
      const double disc = B * B - 4 * A * C;
      if (!(A > 0.0) || disc < 0.0) return false;
      const double r[2] = {(-B + std::sqrt(disc)) / (2 * A), (-B - std::sqrt(disc)) / (2 * A)};
      // The root that keeps going the way the path went (forward in lambda at the start).
      auto score = [&](double root) {
        const Eigen::VectorXd dx = v - root * b;
        return previous_increment_.size() ? dx.dot(previous_increment_) : root;
      };
      dl = score(r[0]) >= score(r[1]) ? r[0] : r[1];
    }
    const Eigen::VectorXd dx = a - dl * b;
    const double alpha = iterations > 0 ? line_search(start, out, dx, dl, R.norm()) : 1.0;
    out.x += alpha * dx;
    out.lambda += alpha * dl;
    if (!out.x.allFinite() || !std::isfinite(out.lambda)) return false;
  }
  return false;
}

/// Backtracking on the residual norm: the face laws switch branches (stick, open, sliding cap,
/// contact), and a full Newton step across such a kink can cycle between branches for good.
/// The first iteration, which carries the load increment, always takes the full step.
double QuasiStaticPath::line_search(const State& start, const State& at, const Eigen::VectorXd& dx,
                                    double dl, double residual) const {
  const ProportionalConstraints& cons = model_.constraints();
  double alpha = 1.0;
  for (int k = 0; k < kLineSearchHalvings; ++k, alpha *= 0.5) {
    std::vector<InterfacePoint> points = start.points;
    const Eigen::VectorXd u = cons.expand(at.x + alpha * dx, at.lambda + alpha * dl);
    if (cons.restrict(model_.forces(u, points, nullptr)).norm() < residual) return alpha;
  }
  return alpha;
}

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
  const CohesiveLaw& law = model_.interfaces().law();
  for (const InterfacePoint& p : s.points)
    if ((p.state == PointState::cohesive && !law.intrinsic()) ||
        law.dissipated_energy(p.history.max_opening) > 0.0)
      return true;
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
    if (!newton(trial, {LoadControl::displacement, trial.lambda}, settled, its)) {
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

/// How far past the next insertion a trial state is: the largest Mohr-Coulomb utilization of the
/// eligible intact points, less one (negative: no event yet). Kinks of the law (the peak, the
/// bilinear kink, delta_c) and contact or unloading switches are not located: the energy-balance
/// check shortens the steps that cross them badly, which costs far fewer solves than locating
/// every kink of every point.
double QuasiStaticPath::event_excess(const State& trial) const {
  if (model_.setup().mode == CrackingMode::pre_inserted) return -1.0;
  return max_utilization(trial, full(trial)) - 1.0;
}

/// One step from `state`: Newton to the step's target (halved on failure); if an insertion falls
/// inside the step, the step is shortened to it, and the failed points are inserted there.
bool QuasiStaticPath::take_step(State& state, int& iterations, int& inserted) {
  const bool elastic_phase =
      options_.control != LoadControl::displacement && !softened(state) && elastic_step_ > 0.0;
  const LoadControl control = elastic_phase ? LoadControl::displacement : options_.control;
  const double tol = options_.event_tolerance;
  double fraction = 1.0, previous_widening = 0.0;
  for (int cut = 0; cut <= options_.max_cuts; ++cut, fraction *= 0.5) {
    State trial;
    if (!newton(state, step_target(state, control, fraction), trial, iterations)) continue;
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
    // the step does not widen the gap. Else it is halved, down to 1/64, while halving helps: the
    // trapezoids' error shrinks about fourfold per halving (eightfold on a smooth stretch), so a
    // widening that halving leaves above kHalvingHelps of itself grows with the path length, not
    // with the step, and cutting further would only multiply the solves.
    const BalanceDrift drift = balance_drift(trial);
    const bool kept = drift.relative_gap <= options_.balance_tolerance || drift.widening <= 0.0;
    const bool halving_helped =
        !(previous_widening > 0.0) || drift.widening < kHalvingHelps * previous_widening;
    if (!kept && halving_helped && fraction > kSmallestBalancedStep) {
      switched_ = switched_before;
      previous_widening = drift.widening;
      continue;
    }
    if (control == LoadControl::arc_length) previous_increment_ = trial.x - state.x;
    state = std::move(trial);
    return true;
  }
  return false;
}

bool QuasiStaticPath::run(const Observer& observe) {
  State state;
  state.x = Eigen::VectorXd::Zero(model_.num_free_dofs());
  state.points = model_.initial_points();
  state.force = Eigen::VectorXd::Zero(model_.num_dofs());
  last_ = point_of(state, 0, PathPoint{});
  observe(last_, full(state), state.points);

  // A probe at a stroke far below anything that softens gives the linear response per unit
  // lambda, and with it the scale of the path.
  const double lambda_probe = 1e-9 * model_.space().mesh().domain().scale() / model_.stroke(1.0);
  State probe;
  int its = 0;
  if (!newton(state, {LoadControl::displacement, lambda_probe}, probe, its)) {
    failure_ = "the elastic probe did not converge";
    return false;
  }
  // The response is linear until something softens: scale the probe so that the largest interface
  // traction is the strength, and estimate the first event from the utilization there.
  const Eigen::VectorXd u1 = full(probe) / lambda_probe;
  double largest = 0.0;
  for (int p : model_.eligible_points(probe.points))
    largest = std::max(largest, model_.interfaces().flux_traction(u1, p).norm());
  const double lambda_scale =
      largest > 0.0 ? model_.interfaces().law().parameters().strength / largest : 1.0;
  double U1 = 0.0;
  for (int p : model_.eligible_points(probe.points))
    U1 = std::max(U1, model_.interfaces().utilization(lambda_scale * u1, p));
  const double lambda_event = U1 > 0.0 && std::isfinite(U1) ? lambda_scale / U1 : lambda_scale;
  const bool gauge_silent = std::abs(cmod(probe)) <= 1e-6 * probe.x.lpNorm<Eigen::Infinity>();
  if (options_.control == LoadControl::cmod && gauge_silent) elastic_step_ = 1.5 * lambda_event;
  const double lambda_span =
      options_.max_stroke > 0.0 ? options_.max_stroke / model_.stroke(1.0) : 2.0 * lambda_event;
  arc_ = probe.x.norm() / lambda_probe * lambda_span / options_.steps;
  if (options_.control == LoadControl::arc_length) elastic_step_ = 1.5 * lambda_event;

  const int limit = 20 * (options_.steps + options_.tail_steps) + 1000;
  for (int step = 1; !finished(state); ++step) {
    if (step > limit) {
      failure_ = "the path did not reach its end in " + std::to_string(limit) + " steps";
      return false;
    }
    int iterations = 0, inserted = 0;
    if (!take_step(state, iterations, inserted)) {
      failure_ = "step " + std::to_string(step) + " did not converge after " +
                 std::to_string(options_.max_cuts) + " cuts (stroke " +
                 std::to_string(model_.stroke(state.lambda)) + ")";
      return false;
    }
    PathPoint p = point_of(state, step, last_);
    p.iterations = iterations;
    p.inserted = inserted;
    observe(p, full(state), state.points);
    last_ = p;
    if (options_.control == LoadControl::arc_length)  // aim at about five iterations a step
      arc_ *= std::clamp(std::sqrt(5.0 / std::max(iterations, 1)), 0.5, 2.0);
  }
  return true;
}

}  // namespace vorodg
