#pragma once
// One explicit simulation of bodies, set up once before its time loop (setup_system, in deal.II's
// words) from plain values: the bodies' mesh (BodiesMesh), ExplicitParameters and the problem's
// loads (ExplicitLoading). It owns the element table, the lumped masses, the elastic integrator
// and the per-cell material variation; bulk viscosity; the internal force (small strain, or
// corotational), the two estimates of the critical step and the step taken; the central-difference
// integrator with its contact laws, its boundary conditions and loads, and the cracks of a
// fragmentation run; and the initial state (each body's velocity and spin). step() advances it
// by one step (with the insertion check after it when it fragments); the integrator's record
// (run->record()) is what an observer reads after each.
#include <cmath>
#include <cstdint>
#include <optional>

#include "core/element/ElasticityIntegrator.hpp"
#include "core/element/ElementTable.hpp"
#include "core/random/MaterialVariation.hpp"
#include "dynamics/BodiesMesh.hpp"
#include "dynamics/BulkViscosity.hpp"
#include "dynamics/CentralDifference.hpp"
#include "dynamics/ContactForces.hpp"
#include "dynamics/ExplicitLoading.hpp"
#include "dynamics/ExplicitParameters.hpp"
#include "dynamics/Fragmentation.hpp"
#include "dynamics/InterfaceCoupling.hpp"
#include "dynamics/LumpedMass.hpp"

namespace vorodg {

class StateArchive;

/// A run is unstable once its kinetic plus elastic energy exceeds this many times the energy put
/// in: a stable run stays within round-off of its input.
constexpr double kEnergyBlowUp = 1e6;

class ExplicitSimulation {
 public:
  /// Builds everything on `bodies` (whose mesh it keeps) from `parameters` and `loading` (both
  /// must outlive it); `seed` is the mesh realization's (the per-cell variation's stream derives
  /// from it), `realization` its index, the same on every mesh level (a random material field's
  /// stream derives from it). Throws InputError for what the mesh cannot carry (a K0 too small
  /// for the law).
  ExplicitSimulation(const ExplicitParameters& parameters, BodiesMesh bodies,
                     const ExplicitLoading& loading, std::uint64_t seed, int realization);
  ExplicitSimulation(const ExplicitSimulation&) = delete;
  ExplicitSimulation& operator=(const ExplicitSimulation&) = delete;

  const ExplicitParameters& parameters;
  const ExplicitLoading& loading;
  const BodiesMesh bodies;
  const ElementTable table;
  const LumpedMass mass;
  const ElasticityIntegrator integrator;
  const ElasticityIntegrator::MeanStrainOperators strain;  // cell mean strains, for the frames
  const MaterialVariation variation;                       // empty: a uniform material

  double dt_lanczos = 0.0, dt_cells = 0.0;  // the two estimates of the critical step
  int lanczos_iterations = 0;
  double dt = 0.0;  // the step taken: safety x the chosen estimate (with the springs' share)
  long steps = 0;   // how many the run is to take
  double contact_stiffness = NAN;  // a fixed displacement penalty k_d (NaN: alpha m / dt^2)
  double bulk_step_ratio = 0.0;    // dt over the undamped critical estimate (bulk viscosity on)

  std::optional<Fragmentation> cracks;        // fragmentation runs only
  std::optional<InterfaceCoupling> coupling;  // interfaces: dg
  std::optional<ContactForces> contact;
  std::optional<BulkViscosity> bulk;  // bulk viscosity on the cells, when a coefficient is > 0
  std::optional<CentralDifference> run;

  const PolygonMesh& mesh() const { return bodies.mesh; }
  /// One step of the integrator, with the insertion check after it when the run fragments.
  void step();
  /// Kinetic plus elastic energy over the energy put in, at the last step.
  double energy_growth() const;
  /// True once that energy is not finite or past kEnergyBlowUp times the input.
  bool unstable() const;

  /// Saves or loads the state of the run after its last step: the integrator's (with its map),
  /// then contact's, the cracks', the interfaces' and bulk viscosity's. Loading needs a
  /// simulation built from the same scene, mesh and seed; it throws CheckpointError if the step
  /// differs (another scene) or the payload does not fit.
  void archive(StateArchive& a);

 private:
  /// The internal force of the (varied) cell matrices; sets the two critical-step estimates.
  InternalForce make_force(const SplitDofMap& dofs, const CrackSites& sites);
  /// Each cell's dilatational speed (its stiffness factor's square root, if the material varies).
  std::vector<double> wave_speeds() const;
  /// The integrator with contact, boundaries, loads, cracks and its initial state.
  void make_integrator(InternalForce force, const SplitDofMap& dofs);
};

}  // namespace vorodg
