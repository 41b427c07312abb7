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
  const PolygonMesh& mesh = model.space().mesh();
  const double side = std::min(mesh.domain().width(), mesh.domain().height());
  force_scale_ = model.interfaces().law().parameters().strength * side;
}

void QuasiStaticPath::factor(const Eigen::SparseMatrix<double>& tangent, Eigen::VectorXd& q) {
  const ProportionalConstraints& cons = model_.constraints();
  std::vector<Eigen::Triplet<double>> lower;
  lower.reserve(tangent.nonZeros() / 2 + tangent.cols());
  for (int j = 0; j < tangent.outerSize(); ++j) {
    const int fj = cons.free_index(j);
    if (fj < 0) continue;
    for (Eigen::SparseMatrix<double>::InnerIterator it(tangent, j); it; ++it) {
      const int fi = cons.free_index(static_cast<int>(it.row()));
      if (fi >= fj) lower.emplace_back(fi, fj, it.value());
    }
  }
  Eigen::SparseMatrix<double> A(cons.num_free(), cons.num_free());
  A.setFromTriplets(lower.begin(), lower.end());
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

bool QuasiStaticPath::newton(const State& start, const Target& target, State& out,
                             int& iterations) {
  const ProportionalConstraints& cons = model_.constraints();
  const Eigen::VectorXd gauge_free = cons.restrict(model_.mouth_gauge());
  const double gauge_lambda = model_.mouth_gauge().dot(cons.reference());
  out.x = start.x;
  out.lambda = start.lambda;
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
    if (iterations > 0 && R.norm() <= options_.tolerance * scale && gap <= 1e-9) return true;
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
    out.x += a - dl * b;
    out.lambda += dl;
    if (!out.x.allFinite() || !std::isfinite(out.lambda)) return false;
  }
  return false;
}

QuasiStaticPath::Target QuasiStaticPath::step_target(const State& start, LoadControl control,
                                                     double fraction) const {
  const double lambda_end = options_.max_stroke / model_.stroke(1.0);
  switch (control) {
    case LoadControl::displacement: {
      const bool elastic = options_.control != LoadControl::displacement;
      const double step = elastic ? elastic_step_ : lambda_end / options_.steps;
      double to = start.lambda + fraction * step;
      if (!elastic) to = std::min(to, lambda_end);
      return {control, to};
    }
    case LoadControl::cmod:
      return {control, std::min(cmod(start) + fraction * options_.max_cmod / options_.steps,
                                options_.max_cmod)};
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
    case LoadControl::displacement: return stroke >= close * options_.max_stroke;
    case LoadControl::cmod: return c >= close * options_.max_cmod;
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
  p.external_work =
      previous.external_work + 0.5 * (previous.load + p.load) * (p.stroke - previous.stroke);
  p.energy = model_.energies(full(s), s.points);
  p.energy.switched = switched_;
  return p;
}

/// Turns the eligible intact points at or past the criterion cohesive, and books the jump in
/// the accounted energy that switching their terms makes.
int QuasiStaticPath::insert_failed_points(State& trial) {
  if (model_.setup().mode == CrackingMode::pre_inserted) return 0;
  const Eigen::VectorXd u = full(trial);
  const double before = model_.energies(u, trial.points).accounted();
  int inserted = 0;
  for (int p : model_.eligible_points(trial.points))
    if (model_.interfaces().utilization(u, p) >= 1.0) {
      trial.points[p].state = PointState::cohesive;
      trial.points[p].offset = model_.interfaces().opening(u, p);
      ++inserted;
    }
  if (inserted == 0) return 0;
  model_.forces(u, trial.points, nullptr);  // the switched points' law takes up their opening
  switched_ += before - model_.energies(u, trial.points).accounted();
  return inserted;
}

/// Whether the step keeps the energy balance: the trapezoids of the external work must not
/// drift from the accounted energy by more than balance_tolerance of the work done so far.
bool QuasiStaticPath::balance_acceptable(const State& trial) const {
  const PathPoint after = point_of(trial, 0, last_);
  const double drift = std::abs(after.external_work - after.energy.accounted()) -
                       std::abs(last_.external_work - last_.energy.accounted());
  return drift <= options_.balance_tolerance * std::max(after.external_work, 1e-300);
}

/// How far past its next event a trial state is: the largest of the Mohr-Coulomb utilization less
/// one over the eligible intact points, and (opening - next kink) / delta_c over the loading
/// cohesive points (between kinks, and before the next insertion, the response is smooth, so
/// trapezoids integrate the work exactly on a linear problem). Negative: no event yet.
double QuasiStaticPath::event_excess(const State& start, const State& trial) const {
  const CohesiveLaw& law = model_.interfaces().law();
  double excess = model_.setup().mode != CrackingMode::pre_inserted
                      ? max_utilization(trial, full(trial)) - 1.0
                      : -1.0;
  const double dc = law.critical_opening();
  for (std::size_t p = 0; p < trial.points.size(); ++p) {
    if (start.points[p].state == PointState::intact) continue;
    const double kink = law.next_kink(start.points[p].history.max_opening);
    if (std::isfinite(kink) && start.points[p].history.max_opening > 0.0)
      excess = std::max(excess, (trial.points[p].history.max_opening - kink) / dc);
  }
  return excess;
}

/// One step from `state`: Newton to the step's target (halved on failure); if an event falls
/// inside the step (an intact point fails, a cohesive point reaches a kink of its law), the step
/// is shortened to it, and failed points are inserted there.
bool QuasiStaticPath::take_step(State& state, int& iterations, int& inserted) {
  const bool elastic_phase =
      options_.control != LoadControl::displacement && !softened(state) && elastic_step_ > 0.0;
  const LoadControl control = elastic_phase ? LoadControl::displacement : options_.control;
  const double tol = options_.event_tolerance;
  double fraction = 1.0;
  for (int cut = 0; cut <= options_.max_cuts; ++cut, fraction *= 0.5) {
    State trial;
    if (!newton(state, step_target(state, control, fraction), trial, iterations)) continue;
    double excess = event_excess(state, trial);
    if (excess > tol) {
      // Regula falsi (Illinois) on the step fraction for the excess to land in [0, tol].
      double lo = 0.0, e_lo = std::min(event_excess(state, state), 0.0), hi = fraction,
             e_hi = excess;
      int side = 0;
      bool ok = true;
      for (int k = 0; k < 60 && (excess < 0.0 || excess > tol); ++k) {
        const double s = std::clamp(lo + (0.5 * tol - e_lo) / (e_hi - e_lo) * (hi - lo),
                                    lo + 1e-9 * (hi - lo), hi - 1e-9 * (hi - lo));
        int its = 0;
        if (!(ok = newton(state, step_target(state, control, s), trial, its))) break;
        iterations += its;
        excess = event_excess(state, trial);
        if (excess < 0.0) {
          lo = s, e_lo = excess;
          if (side == -1) e_hi *= 0.5;
          side = -1;
        } else {
          hi = s, e_hi = excess;
          if (side == 1) e_lo *= 0.5;
          side = 1;
        }
      }
      if (!ok || excess < 0.0) continue;
    }
    const double switched_before = switched_;
    inserted = insert_failed_points(trial);
    if (!balance_acceptable(trial) && fraction > kSmallestBalancedStep) {
      switched_ = switched_before;
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

  const int limit = 20 * options_.steps + 1000;
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
