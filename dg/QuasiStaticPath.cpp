#include "dg/QuasiStaticPath.hpp"

#include <algorithm>
#include <cmath>

#include "core/io/StateArchive.hpp"
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
  if (!condense_decided_) {
    condense_decided_ = true;
    if (options_.condense_faces && model_.setup().mode == CrackingMode::pre_inserted) {
      std::vector<int> varying;
      for (int dof : model_.face_end_dofs())
        if (const int free = cons.free_index(dof); free >= 0) varying.push_back(free);
      condensed_.emplace(std::move(varying));
    }
  }
  q = cons.restrict(tangent * cons.reference());  // dR / d lambda
  if (condensed_) {
    try {
      if (condensed_->factorize(A)) {
        ++factorizations_;
        return;
      }
    } catch (const NumericalError&) {  // its bulk block is not definite, or S singular
    }
    condensed_.reset();  // factored whole from now on
  }
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

Eigen::MatrixXd QuasiStaticPath::solve(const Eigen::MatrixXd& rhs) const {
  return condensed_ ? condensed_->solve_many(rhs) : solver_.solve_many(rhs);
}

double QuasiStaticPath::control_gap(const State& start, const State& at, const Eigen::VectorXd& u,
                                    const Target& target) const {
  switch (target.control) {
    case LoadControl::displacement: return std::abs(target.value - at.lambda);
    case LoadControl::cmod:
      return std::abs(target.value - model_.mouth_gauge().dot(u)) /
             std::max(std::abs(target.value), 1e-300);
    case LoadControl::arc_length:
      return std::abs(released(start, at) - target.value) / target.value;
  }
  return 0.0;
}

std::optional<double> QuasiStaticPath::load_step(const State& start, const State& at,
                                                 const Target& target,
                                                 const NewtonSolves& n) const {
  if (target.control == LoadControl::displacement) return target.value - at.lambda;
  const ProportionalConstraints& cons = model_.constraints();
  if (target.control == LoadControl::cmod) {
    const Eigen::VectorXd gauge_free = cons.restrict(model_.mouth_gauge());
    const double gauge_lambda = model_.mouth_gauge().dot(cons.reference());
    const double c = model_.mouth_gauge().dot(n.u);
    const double denominator = gauge_lambda - gauge_free.dot(n.b);
    if (denominator == 0.0) return std::nullopt;
    return (target.value - c - gauge_free.dot(n.a)) / denominator;
  }
  // released(start, x + dx, lambda + dl) = s, linearized: dP = t (q.dx + k_rr dl)
  const double t = model_.setup().thickness, p0 = model_.load(start.force);
  const Eigen::VectorXd& r = cons.reference();
  const double k_rr = r.dot(n.K * r);
  const double denominator = 0.5 * (p0 - start.lambda * t * (k_rr - n.q.dot(n.b)));
  if (denominator == 0.0) return std::nullopt;
  return (target.value - released(start, at) + 0.5 * start.lambda * t * n.q.dot(n.a)) / denominator;
}

bool QuasiStaticPath::newton(const State& start, const Target& target, State& out, int& iterations,
                             const Guess& guess) {
  const ProportionalConstraints& cons = model_.constraints();
  out.x = start.x;
  out.lambda = start.lambda;
  if (guess.from && guess.to) {  // between two converged states of a smooth stretch
    out.x = (1.0 - guess.weight) * guess.from->x + guess.weight * guess.to->x;
    out.lambda = (1.0 - guess.weight) * guess.from->lambda + guess.weight * guess.to->lambda;
  }
  const bool guessed = guess.from && guess.to;
  const int budget = target.max_iterations > 0 ? target.max_iterations : options_.max_iterations;
  Eigen::VectorXd q;              // dR / d lambda of the factored tangent
  bool have_factor = false;       // the solver holds this Newton run's last factor
  double reused_from = INFINITY;  // the residual when the factor was last reused
  std::vector<double> history;    // relative residuals, for the stagnation exit
  for (iterations = 0; iterations <= budget; ++iterations) {
    const Eigen::VectorXd u = full(out);
    out.points = start.points;
    Eigen::SparseMatrix<double> K;
    out.force = model_.forces(u, out.points, &K);
    const Eigen::VectorXd R = cons.restrict(out.force);
    const double gap = control_gap(start, out, u, target);
    // Residual relative to the larger of the strength's force scale and the reactions (whose
    // round-off floor it shares).
    const double reactions = std::sqrt(std::max(out.force.squaredNorm() - R.squaredNorm(), 0.0));
    const double scale = std::max(force_scale_, reactions);
    const double relative = R.norm() / scale;
    if ((iterations > 0 || guessed) && relative <= options_.tolerance && gap <= 1e-9) return true;
    // Settling (its own budget) is given every iteration: an unsettled body loses energy.
    const bool may_stop_early = target.max_iterations == 0;
    if (iterations == budget || (may_stop_early && stagnates(history, relative))) return false;
    history.push_back(relative);
    // Within kReuseWindow of convergence, with the extra equation met, the last factor finishes
    // the job as well as a new one (a modified Newton step), for a back-solve instead of a
    // factorization; a reuse that does not contract tenfold is not repeated.
    const bool reuse = have_factor && gap <= 1e-9 &&
                       relative <= kReuseWindow * options_.tolerance &&
                       relative <= 0.1 * reused_from;
    if (reuse) {
      reused_from = relative;
    } else {
      try {
        factor(K, q);
      } catch (const NumericalError&) {
        return false;
      }
      have_factor = true, reused_from = INFINITY;
    }
    Eigen::MatrixXd rhs(R.size(), 2);
    rhs << -R, q;
    const Eigen::MatrixXd ab = solve(rhs);  // both in one pass over the factor
    const Eigen::VectorXd a = ab.col(0), b = ab.col(1);
    const std::optional<double> step = load_step(start, out, target, {u, K, q, a, b});
    if (!step) return false;
    const double dl = *step;
    const Eigen::VectorXd dx = a - dl * b;
    const double alpha = iterations > 0 ? line_search(start, out, dx, dl, R.norm()) : 1.0;
    out.x += alpha * dx;
    out.lambda += alpha * dl;
    if (!out.x.allFinite() || !std::isfinite(out.lambda)) return false;
  }
  return false;
}

/// Newton is given up early, from kStagnationStart iterations on, when the residual has not
/// halved over the last kStagnationWindow iterations: the face laws' branches make it cycle (a
/// kink crossed back and forth), and the remaining iterations would only delay the halving.
bool QuasiStaticPath::stagnates(const std::vector<double>& history, double relative) {
  const int n = static_cast<int>(history.size());
  if (n < kStagnationStart) return false;
  const double best = *std::min_element(history.end() - kStagnationWindow, history.end());
  return relative > 0.5 * best;
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

/// Where the first pre-inserted (intrinsic) point reaches its peak, by scaling the probe: the law
/// is linear until then, with the effective opening sigma_c / K0 at the peak. The probe's own
/// lambda if nothing opens (no point is cohesive).
double QuasiStaticPath::first_peak(const State& probe, double lambda_probe) const {
  const CohesiveInterfaces& faces = model_.interfaces();
  if (!(faces.law().parameters().initial_stiffness > 0.0)) return lambda_probe;
  const Eigen::VectorXd u = full(probe);
  double nearest = 0.0;  // the largest effective opening over the point's peak opening
  for (int p = 0; p < faces.num_points(); ++p) {
    if (probe.points[p].state != PointState::cohesive) continue;
    const CohesiveLaw& law = faces.law(p);
    CohesiveLaw::State scratch = probe.points[p].history;  // the law's effective opening only
    const Eigen::Vector2d g = faces.opening(u, p) - probe.points[p].offset;
    const CohesiveParameters& c = law.parameters();
    const double peak_opening = c.strength / c.initial_stiffness;
    nearest = std::max(nearest, law.respond(g, scratch).effective_opening / peak_opening);
  }
  if (!(nearest > 0.0)) return lambda_probe;
  return lambda_probe / nearest;
}

/// The energy released from `start` to `at` when every unloading is secant (Clapeyron: the
/// stored energy is P lambda / 2, P the load conjugate to lambda): the trapezoid of the external
/// work less the change in stored energy, (P_0 lambda - P lambda_0) / 2. It grows along the path
/// through snap-back, where neither the stroke nor any displacement norm does (after Gutierrez,
/// and Verhoosel, Remmers and Gutierrez).
double QuasiStaticPath::released(const State& start, const State& at) const {
  return 0.5 * (model_.load(start.force) * at.lambda - model_.load(at.force) * start.lambda);
}

bool QuasiStaticPath::calibrate(const State& state) {
  // A probe at a stroke far below anything that softens gives the linear response per unit
  // lambda, and with it the scale of the path.
  const double lambda_probe = 1e-9 * model_.space().mesh().domain().scale() / model_.stroke(1.0);
  State probe;
  int its = 0;
  // The probe is piecewise linear, not linear: faces under closure switch to the contact
  // penalty, and on fine meshes finding which do takes Newton more than a step's budget.
  if (!newton(state, {LoadControl::displacement, lambda_probe, kProbeIterations}, probe, its)) {
    failure_ = "the elastic probe did not converge";
    return false;
  }
  probe_.x = probe.x;
  probe_.lambda = probe.lambda;
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
  const double lambda_event =
      U1 > 0.0 && std::isfinite(U1) ? lambda_scale / U1 : first_peak(probe, lambda_probe);
  const bool gauge_silent = std::abs(cmod(probe)) <= 1e-6 * probe.x.lpNorm<Eigen::Infinity>();
  if (options_.control == LoadControl::cmod && gauge_silent) elastic_step_ = 1.5 * lambda_event;
  // Arc-length: the energy released per step, starting from G x height x thickness (a crack
  // across the whole body) over the nominal steps.
  arc_start_ = crack_energy() / options_.steps;
  arc_ = arc_start_;
  if (options_.control == LoadControl::arc_length) elastic_step_ = 1.5 * lambda_event;
  return true;
}

bool QuasiStaticPath::end_at_failed_step(const State& state, int step) {
  if (softened(state) && std::abs(last_.load) <= kFinalSnapLoad * peak_load_) {
    const std::string after = " after cmod " + std::to_string(last_.cmod) + " (load " +
                              std::to_string(std::abs(last_.load) / peak_load_) + " of the peak)";
    stop_reason_ =
        jumped_ ? "the last ligament snapped" + after +
                      ": a jump no quasi-static control follows, not booked"
                : "the remnants could not be followed" + after + ": a step failed after every cut";
    return true;
  }
  const std::string where = " (stroke " + std::to_string(model_.stroke(state.lambda)) + ", cmod " +
                            std::to_string(cmod(state)) + ")";
  failure_ = jumped_ ? "step " + std::to_string(step) +
                           ": the path jumped to another equilibrium, the energy balance "
                           "missing more than " +
                           std::to_string(kJumpLimit) + " of the work at the smallest cut" + where +
                           ": a snap that " + load_control_name(options_.control) +
                           " control cannot follow"
                     : "step " + std::to_string(step) + " did not converge after " +
                           std::to_string(options_.max_cuts) + " cuts" + where;
  return false;
}

bool QuasiStaticPath::run(const Observer& observe, const StepHook& after_step) {
  State& state = state_;
  if (!started_) {
    state.x = Eigen::VectorXd::Zero(model_.num_free_dofs());
    state.points = model_.initial_points();
    state.force = Eigen::VectorXd::Zero(model_.num_dofs());
    last_ = point_of(state, 0, PathPoint{});
    observe(last_, full(state), state.points);
    if (!calibrate(state)) return false;
    started_ = true;
  }
  const int limit = 20 * (options_.steps + options_.tail_steps) + 1000;
  for (int step = step_ + 1; !finished(state); ++step) {
    if (step > limit) {
      failure_ = "the path did not reach its end in " + std::to_string(limit) + " steps";
      return false;
    }
    int iterations = 0, inserted = 0;
    if (!take_step(state, iterations, inserted)) {
      return end_at_failed_step(state, step);
    }
    PathPoint p = point_of(state, step, last_);
    p.iterations = iterations;
    p.inserted = inserted;
    observe(p, full(state), state.points);
    last_ = p;
    peak_load_ = std::max(peak_load_, std::abs(p.load));
    if (softened(state) && std::abs(p.load) <= kVanishedLoad * peak_load_) {
      stop_reason_ = "the load vanished at cmod " + std::to_string(p.cmod) + " (" +
                     std::to_string(std::abs(p.load) / peak_load_) + " of the peak)";
      return true;
    }
    if (options_.control == LoadControl::arc_length)  // about five iterations, never past ds_0
      arc_ = std::min(arc_ * std::clamp(std::sqrt(5.0 / std::max(iterations, 1)), 0.5, 2.0),
                      arc_start_);
    step_ = step;
    if (after_step) after_step(step);
  }
  return true;
}

void QuasiStaticPath::archive(StateArchive& a) {
  a.vector("path.x", state_.x);
  a.value("path.lambda", state_.lambda);
  a.vector("path.points", state_.points);
  a.vector("path.force", state_.force);
  a.value("path.arrival_load", state_.arrival_load);
  a.value("path.step", step_);
  a.value("path.started", started_);
  a.value("path.jumped", jumped_);
  a.value("path.peak_load", peak_load_);
  a.text("path.stop_reason", stop_reason_);
  a.value("path.last", last_);
  a.value("path.switched", switched_);
  a.value("path.indefinite", indefinite_);
  a.value("path.factorizations", factorizations_);
  a.value("path.force_scale", force_scale_);
  a.value("path.elastic_step", elastic_step_);
  a.vector("path.probe.x", probe_.x);
  a.value("path.probe.lambda", probe_.lambda);
  a.value("path.arc", arc_);
  a.value("path.arc_start", arc_start_);
}

}  // namespace vorodg
