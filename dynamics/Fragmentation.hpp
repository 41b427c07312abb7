#pragma once
// The cracks of one fragmentation run (docs/fragmentation.md): the cohesive law with K0 in units
// of E / h_avg, the Mohr-Coulomb insertion check on the interior edges the problem lets crack
// (every one unless its CrackSites say otherwise), the faces there at t = 0, and DynamicFracture
// on the run's integrator; the stable step with the faces' springs; the energy balance with the
// law's closed forms; the fragments and the largest one's turn.
#include <optional>
#include <string>
#include <vector>

#include "core/element/ElasticityIntegrator.hpp"
#include "core/io/VtuMesh.hpp"
#include "core/random/MaterialVariation.hpp"
#include "dynamics/DynamicFracture.hpp"
#include "dynamics/ExplicitLoading.hpp"
#include "dynamics/ExplicitParameters.hpp"
#include "dynamics/GlobalTimeStep.hpp"
#include "dynamics/StableTimeStep.hpp"
#include "fracture/Fragments.hpp"

namespace vorodg {

class StateArchive;

/// The energy balance with the law's energies a run must keep, of the input energy.
constexpr double kLawBalanceLimit = 0.01;

class Fragmentation {
 public:
  /// The law and criterion of `p` on `mesh` with the problem's crack `sites`; throws InputError
  /// naming cohesive keys the mesh cannot carry (a K0 too small for the law's peak to come before
  /// delta_c).
  Fragmentation(const ExplicitParameters& p, const PolygonMesh& mesh, double h_avg,
                CrackSites sites);

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
  /// The turn of the largest of `pieces` (mass-weighted mean rotation of its cells, radians).
  double main_body_rotation(const Fragments& pieces, const LumpedMass& mass) const;
  /// The faces (after attach).
  const CohesiveForces& cohesive() const { return *cohesive_; }
  /// The cracks' driver (after attach): their events, the broken state, the check's times.
  const DynamicFracture& fracture() const { return *fracture_; }
  /// The interfaces' activation (coupled from the start), or nullptr.
  const InterfaceActivation* activation() const { return activation_.get(); }
  /// The fully broken edges now (after attach): what separates the fragments.
  CrackState broken_state() const { return fracture_->broken_state(); }
  const PolygonMesh& mesh() const { return mesh_; }
  /// The run (after attach).
  const CentralDifference& run() const { return *run_; }
  /// The largest balance error so far, when it first passed kLawBalanceLimit (NaN: never), and
  /// the input energy at the last check.
  double worst_balance() const { return worst_balance_; }
  double breach_time() const { return breach_time_; }
  double input_energy() const { return input_energy_; }

  /// Saves or loads the cracks, the faces and the law balance's account (a checkpoint).
  void archive(StateArchive& a);

 private:
  const PolygonMesh& mesh_;
  CohesiveLaw law_;
  MohrCoulomb criterion_;
  CrackSites sites_;            // the problem's: where cracks may form, and those at t = 0
  std::vector<char> eligible_;  // per edge: checked by the criterion
  double friction_;             // on closed faces
  ClosureStiffness closure_;    // the overclosure penalty
  bool turning_frames_;         // the faces' frames turn with them (corotational kinematics)
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
