#pragma once
// Quasi-static path following for cohesive fracture (docs/fracture.md "Path following"). The
// machine's stroke is a load parameter lambda (ProportionalConstraints); each step solves the
// equilibrium R(u, lambda) = 0 with Newton on the consistent tangent and one extra equation that
// says how far the step goes:
//   displacement: lambda = lambda_0 + d lambda (snap-back cannot be followed);
//   cmod:         the crack mouth opening gauge . u = cmod_0 + d cmod (indirect displacement
//                 control: the opening grows monotonically through snap-back);
//   arc-length:   the energy released over the step, (P_0 lambda - P lambda_0) / 2 with P the
//                 load conjugate to lambda, is ds (dissipation-based arc-length; it grows through
//                 snap-back, where a displacement norm turns back).
// The extra equation is solved by bordering: two back-solves with one factor per iteration. The
// symbolic factorization is kept for the run (the pattern never changes); the factor is LL^T
// until the tangent is indefinite, LDL^T after. A step that fails is halved, up to max_cuts
// times; a run that still fails keeps every converged step and says so.
// Before anything softens the response is linear, and cmod or arc-length control may have
// nothing to hold on to (an intact crack line does not open): steps are displacement-controlled
// until the first point softens. Extrinsic insertion is an event located inside the step: the
// step is shortened (regula falsi) until the largest Mohr-Coulomb utilization of the eligible
// intact points lies in [1, 1 + event_tolerance], and the points at or above 1 turn cohesive there.
#include <Eigen/Core>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/solve/BlockPattern.hpp"
#include "core/solve/CondensedCholesky.hpp"
#include "core/solve/SparseCholesky.hpp"
#include "dg/CohesiveFracture.hpp"

namespace vorodg {

class StateArchive;

enum class LoadControl { displacement, cmod, arc_length };
/// Parses displacement, cmod, arc-length; throws InputError otherwise.
LoadControl parse_load_control(const std::string& name);
std::string load_control_name(LoadControl control);

struct PathOptions {
  LoadControl control = LoadControl::displacement;
  double max_stroke = 0.0;  // end of the path in stroke (displacement, arc-length), if > 0
  double max_cmod = 0.0;    // end of the path in crack mouth opening (cmod, arc-length), if > 0
  int steps = 100;          // nominal steps to the end of the path
  /// An optional tail after max_stroke (displacement) or max_cmod (cmod): on to tail_end, in the
  /// same measure, in tail_steps equal steps (fine steps through the peak, coarse ones after).
  double tail_end = 0.0;
  int tail_steps = 0;
  int max_iterations = 15;   // quadratic convergence needs few; more only delays the cut
  double tolerance = 1e-10;  // residual norm relative to the force scale
  int max_cuts = 10;
  /// How far past an insertion (in Mohr-Coulomb utilization) the located point may lie.
  double event_tolerance = 1e-6;
  /// A step is halved (down to 1/64 of its length) while, after it, the energy balance misses
  /// by more than this fraction of the external work (and by more than before the step).
  double balance_tolerance = 5e-4;
  /// With pre-inserted faces, factor the bulk once and each tangent's faces through their Schur
  /// complement (CondensedCholesky; the same path to Newton's tolerance); false: the whole
  /// tangent every time.
  bool condense_faces = true;
  /// Where a step fails at every cut before anything has softened, try every cut again with
  /// Newton started from the elastic probe scaled to the target (QuasiStaticStep.cpp); false:
  /// the run fails there, as it did before this existed.
  bool restart_from_probe = true;
};

/// One converged point of the path; forces in newtons and energies in joules (thickness in).
struct PathPoint {
  int step = 0;
  double stroke = 0.0, cmod = 0.0, load = 0.0;
  double external_work = 0.0;
  FractureEnergies energy;
  int iterations = 0;
  int inserted = 0;  // points that turned cohesive at this point
  /// |W - stored - dissipated| / W (0 before any work is done).
  double balance_error() const;
};

class QuasiStaticPath {
 public:
  QuasiStaticPath(const CohesiveFracture& model, const PathOptions& options);
  using Observer = std::function<void(const PathPoint&, const Eigen::VectorXd& u,
                                      const std::vector<InterfacePoint>& points)>;
  /// Follows the path, reporting every converged point (step 0 is the unloaded state). Returns
  /// false if a step failed after every cut; failure() says why.
  /// Called after every converged step with its number (after the observer): where a run
  /// checkpoints, or stops by throwing.
  using StepHook = std::function<void(int step)>;
  bool run(const Observer& observe, const StepHook& after_step = {});
  /// Saves or loads the path after its last converged step (a checkpoint). Loaded into a path
  /// built on the same model and options, run() continues with the next step, without observing
  /// the start again; the solver analyses its first tangent afresh (the same analysis).
  void archive(StateArchive& a);
  const std::string& failure() const { return failure_; }
  /// Why a complete path ended before its end point (empty if it reached it).
  const std::string& stop_reason() const { return stop_reason_; }
  int factorizations() const { return factorizations_; }
  /// Whether the tangents are being factored through the faces' Schur complement.
  bool condensing() const { return condensed_.has_value(); }
  /// The last converged point.
  const PathPoint& last() const { return last_; }

 private:
  struct State {
    Eigen::VectorXd x;  // free DOFs
    double lambda = 0.0;
    std::vector<InterfacePoint> points;
    Eigen::VectorXd force;      // internal forces on all DOFs
    double arrival_load = NAN;  // after an insertion: the load before the body settled
  };
  struct Target {
    LoadControl control;
    double value;            // lambda, cmod or arc length
    int max_iterations = 0;  // 0: PathOptions::max_iterations
  };
  /// A starting point for Newton: (1 - weight) from + weight to (both null: the start).
  struct Guess {
    const State* from = nullptr;
    const State* to = nullptr;
    double weight = 0.0;
  };
  bool newton(const State& start, const Target& target, State& out, int& iterations,
              const Guess& guess);
  bool newton(const State& start, const Target& target, State& out, int& iterations) {
    return newton(start, target, out, iterations, Guess{nullptr, nullptr, 0.0});
  }
  /// How far the control's extra equation is from holding at `at` (u: its full displacement).
  double control_gap(const State& start, const State& at, const Eigen::VectorXd& u,
                     const Target& target) const;
  /// What a Newton iteration solved: the full displacement, the tangent, dR/d lambda and the
  /// two solutions a = K^-1 (-R), b = K^-1 q.
  struct NewtonSolves {
    const Eigen::VectorXd& u;
    const Eigen::SparseMatrix<double>& K;
    const Eigen::VectorXd &q, &a, &b;
  };
  /// The iteration's load-factor step dl that meets the control's linearized equation; none
  /// where that equation is singular.
  std::optional<double> load_step(const State& start, const State& at, const Target& target,
                                  const NewtonSolves& n) const;
  double line_search(const State& start, const State& at, const Eigen::VectorXd& dx, double dl,
                     double residual) const;
  static bool stagnates(const std::vector<double>& history, double relative);
  static constexpr int kStagnationStart = 10, kStagnationWindow = 4;
  static constexpr double kReuseWindow = 1e3;
  static constexpr int kLineSearchHalvings = 6;
  static constexpr int kEventSearches = 60;
  static constexpr int kSettlingRounds = 100;
  static constexpr int kSettlingIterations = 60;
  static constexpr int kProbeIterations = 60;
  static constexpr double kHalvingHelps = 0.6;  // a kink: under 1/2; a jump: about 1
  double staged_target(double at, double main_end, double fraction) const;
  Target step_target(const State& start, LoadControl control, double fraction) const;
  double max_utilization(const State& s, const Eigen::VectorXd& u) const;
  double released(const State& start, const State& at) const;
  double first_peak(const State& probe, double lambda_probe) const;
  Eigen::VectorXd full(const State& s) const { return model_.constraints().expand(s.x, s.lambda); }
  double cmod(const State& s) const { return model_.mouth_gauge().dot(full(s)); }
  bool softened(const State& s) const;
  bool finished(const State& s) const;
  void factor(const Eigen::SparseMatrix<double>& tangent, Eigen::VectorXd& q);
  /// Solves with the last factorization (condensed or whole), a column per right-hand side.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& rhs) const;
  PathPoint point_of(const State& s, int step, const PathPoint& previous) const;
  /// One step, cut down to 1 / 2^max_cuts as needed; where every cut fails before anything has
  /// softened, every cut again with Newton started from the elastic probe.
  bool take_step(State& state, int& iterations, int& inserted);
  bool try_step(State& state, int& iterations, int& inserted, bool from_probe);
  /// Newton for `target` started from the elastic probe scaled to it (QuasiStaticStep.cpp says
  /// why). False where that does not apply or fails.
  bool newton_from_probe(const State& state, const Target& target, State& out, int& iterations);
  /// The elastic probe from the unloaded `state`: the path's scale, the load factor of the first
  /// event, and the first step of the controls that need one. False (failure_ set) if the probe
  /// does not converge.
  bool calibrate(const State& state);
  /// After a step failed at every cut: true (stop_reason_ set) if the path ends there as a snap
  /// of the softened remnants, false (failure_ set) otherwise.
  bool end_at_failed_step(const State& state, int step);
  double event_excess(const State& trial) const;
  int insert_failed_points(State& trial);
  struct BalanceDrift {
    double widening;      // gap after the step less gap before (J)
    double relative_gap;  // gap after the step over the external work
  };
  BalanceDrift balance_drift(const State& trial) const;
  static constexpr double kSmallestBalancedStep = 1.0 / 64.0;
  /// A step that still widens the balance's gap by this fraction of jump_scale() at its smallest
  /// cut has not followed the path but jumped to another equilibrium (faces past delta_c with no
  /// work done): the run fails there rather than book the jump.
  static constexpr double kJumpLimit = 2e-3;
  double jump_scale(const State& trial) const;
  /// G x height x thickness: the fracture energy of a crack across the whole body.
  double crack_energy() const;
  /// Once softened, the path ends when the load falls to this fraction of its peak: the halves
  /// then hinge about what is left of the ligament, and further opening measures nothing.
  static constexpr double kVanishedLoad = 1e-4;
  /// A step that jumps or fails from a state whose load has already fallen to this fraction of
  /// its peak ends the test (the beam's final snap, or remnants no step can follow), not a
  /// failure (docs/fracture.md).
  static constexpr double kFinalSnapLoad = 1e-2;
  State state_;           // after the last converged step
  int step_ = 0;          // that step
  bool started_ = false;  // the start observed and the path calibrated
  bool jumped_ = false;
  double peak_load_ = 0.0;
  std::string stop_reason_;
  PathPoint last_;         // the last converged point
  double switched_ = 0.0;  // energy booked at insertions (PathPoint::energy.switched)

  const CohesiveFracture& model_;
  PathOptions options_;
  SparseCholesky solver_;
  /// With pre-inserted faces only the faces' end DOFs change the tangent: the bulk is factored
  /// once and each Newton step factors the faces' Schur complement (reset, for the whole
  /// factorization, if the tangent ever changes elsewhere).
  std::optional<CondensedCholesky> condensed_;
  bool condense_decided_ = false;
  std::optional<RestrictedLower> free_lower_;  // the tangent's free-free lower triangle
  bool indefinite_ = false, analysed_ = false;
  int factorizations_ = 0;
  double force_scale_ = 1.0;
  double elastic_step_ = 0.0;  // stroke per step before anything softens (cmod, arc-length)
  State probe_;                // the converged elastic probe (x and lambda)
  double arc_ = 0.0;           // arc-length: the energy the current step releases
  double arc_start_ = 0.0;     // and its first (and largest) value
  std::string failure_;
};

/// What a caller may watch of a fracture run, point by point: the model, the converged point and
/// the states of the interface points (a study records them; the Python layer collects the
/// curve and the cracks from them).
using FracturePathObserver = std::function<void(
    const CohesiveFracture& model, const PathPoint& point, const std::vector<InterfacePoint>&)>;

}  // namespace vorodg
