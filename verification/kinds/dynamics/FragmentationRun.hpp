#pragma once
// The cracks of one fragmentation run (docs/fragmentation.md): the cohesive law with K0 in units
// of E / h_avg, the Mohr-Coulomb insertion check on the interior edges the problem lets crack
// (every one unless it says otherwise, DynamicsProblem::crack_sites), faces the problem puts in at
// t = 0, and DynamicFracture on the run's integrator; the stable step with the faces' springs;
// after the run, the fragments and the crack log as files, and the figures for results.csv.
#include <filesystem>
#include <optional>
#include <string>

#include "core/element/ElasticityIntegrator.hpp"
#include "core/io/VtuMesh.hpp"
#include "dynamics/DynamicFracture.hpp"
#include "dynamics/GlobalTimeStep.hpp"
#include "dynamics/MaterialVariation.hpp"
#include "dynamics/StableTimeStep.hpp"
#include "fracture/Fragments.hpp"
#include "verification/kinds/dynamics/DynamicsProbe.hpp"
#include "verification/kinds/dynamics/DynamicsScene.hpp"

namespace vorodg {

/// The energy balance with the law's energies a run must keep, of the input energy.
constexpr double kLawBalanceLimit = 0.01;

class FragmentationRun {
 public:
  /// The law and criterion of `scene` on `mesh`; throws InputError naming cohesive keys the
  /// mesh cannot carry (a K0 too small for the law's peak to come before delta_c).
  FragmentationRun(const DynamicsScene& scene, const PolygonMesh& mesh, double h_avg);

  /// Each crack face's overclosure penalty becomes its interface's penalty eps in `coupling` (the
  /// run's interfaces coupled from the start), as in the quasi-static solver, instead of a
  /// fraction of K0 (cohesive.closure_stiffness "interface"). Call before the step's bounds and
  /// attach.
  void close_as_interfaces(const InterfaceCoupling& coupling);
  /// An upper bound of the largest eigenvalue of the cells and the faces' springs together, for
  /// every crack pattern the run can reach: the cells' bound plus the springs' (Gershgorin).
  /// `coupling_eigenvalue`: the bound of coupled interfaces (InterfaceCoupling), added to it.
  double eigenvalue_bound(const StableTimeStep& cells, const LumpedMass& mass,
                          double coupling_eigenvalue = 0.0) const;
  /// The critical step of the same system estimated, not bounded (time.estimate "lanczos"):
  /// Lanczos on the cells (`force`, the linear cell matrices) and the faces' stiffest springs on
  /// the map split along every face that may crack, whose largest eigenvalue is that of every
  /// crack pattern the run can reach (CohesiveForces::spring_stiffness), capped by `bound`
  /// (eigenvalue_bound's). Without interfaces coupled from the start.
  GlobalTimeStep estimated_step(InternalForce& force, const LumpedMass& mass, double bound) const;
  /// Starts cracking on `run` (before its initialize()) of a material varying as `variation`
  /// (empty: uniform; the run's cell matrices already scaled); with `contact` (the run's), cracks
  /// expose new surface to it. With `coupling` (the run's interfaces coupled from the start),
  /// cracks are activated on the consistent interface traction (InterfaceActivation) instead
  /// of inserted.
  void attach(CentralDifference& run, const ElasticityIntegrator& integrator,
              const MaterialVariation& variation, ContactForces* contact, int threads,
              InterfaceCoupling* coupling = nullptr);
  /// One step of the run with the insertion check after it.
  void step();
  /// After a step (the run calls it at its history steps: the closed forms cost a pass over the
  /// cracked edges): the balance with the closed forms of the cohesive law and of contact
  /// (kinetic + elastic + dissipated + stored + contact springs + what contact's velocity
  /// penalty and friction took, against what was put in), relative to the input energy; its largest
  /// value so far is kept.
  void check_balance(const StepRecord& record);
  /// For a .vtu frame: per cell its fragment (components across the fully broken edges) and its
  /// number of cracked edges.
  std::vector<VtuField> cell_fields(const LumpedMass& mass) const;
  /// Fills the fragmentation figures of `m` and writes fragments/<id>.csv and cracks/<id>.csv.
  /// The largest fragment's turn (DynamicsMeasures::main_body_rotation).
  double main_body_rotation(const Fragments& pieces, const LumpedMass& mass) const;
  void finish(const std::filesystem::path& out, const std::string& id, const LumpedMass& mass,
              DynamicsMeasures& m) const;
  /// The faces (after attach).
  const CohesiveForces& cohesive() const { return *cohesive_; }
  /// The fully broken edges now (after attach): what separates the fragments.
  CrackState broken_state() const { return fracture_->broken_state(); }

 private:
  const PolygonMesh& mesh_;
  CohesiveLaw law_;
  MohrCoulomb criterion_;
  CrackSites sites_;            // the problem's: where cracks may form, and those at t = 0
  std::vector<char> eligible_;  // per edge: checked by the criterion
  double friction_;             // on closed faces
  ClosureStiffness closure_;    // the overclosure penalty
  bool turning_frames_;         // the faces' frames turn with them (corotational kinematics)
  Rectangle body_;  // the (first) body, and the wall's point if there is one: where cracks are
  std::optional<Point> impact_;
  std::unique_ptr<CohesiveForces> cohesive_;
  /// Per edge: whether it may carry a face in this run (eligible, or there from t = 0).
  std::vector<char> spring_edges() const;
  std::unique_ptr<CrackInsertion> insertion_;
  std::unique_ptr<InterfaceActivation> activation_;
  std::unique_ptr<DynamicFracture> fracture_;
  CentralDifference* run_ = nullptr;
  const ContactForces* contact_ = nullptr;
  double start_ = 0.0, worst_balance_ = 0.0, input_energy_ = 0.0;
  double breach_time_ = NAN;  // when the balance first passed kLawBalanceLimit
};

}  // namespace vorodg
