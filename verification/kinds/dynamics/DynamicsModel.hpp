#pragma once
// The model of one dynamics run, set up once before its time loop (setup_system, in deal.II's
// words): the bodies' mesh, the element table, the lumped masses, the elastic integrator and the
// per-cell material variation; bulk viscosity; the internal force (small strain, or corotational),
// the two estimates of the critical step and the step taken; the central-difference integrator with
// its contact, its boundary conditions and loads, and the cracks of a fragmentation run; and the
// initial state (each body's velocity and spin).
#include <cmath>
#include <optional>

#include "core/element/ElasticityIntegrator.hpp"
#include "core/element/ElementTable.hpp"
#include "dynamics/BulkViscosity.hpp"
#include "dynamics/CentralDifference.hpp"
#include "dynamics/ContactForces.hpp"
#include "dynamics/InterfaceCoupling.hpp"
#include "dynamics/LumpedMass.hpp"
#include "dynamics/MaterialVariation.hpp"
#include "verification/kinds/dynamics/DynamicsMesh.hpp"
#include "verification/kinds/dynamics/FragmentationRun.hpp"

namespace vorodg {

class DynamicsModel {
 public:
  /// Builds everything of realization `id` of `scene`; throws InputError for what the mesh
  /// cannot carry (a projectile narrower than the cells, a K0 too small for the law).
  DynamicsModel(const DynamicsScene& scene, const EnsembleRunId& id);
  DynamicsModel(const DynamicsModel&) = delete;
  DynamicsModel& operator=(const DynamicsModel&) = delete;

  const DynamicsScene& scene;
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

  std::optional<FragmentationRun> cracks;     // fragmentation runs only
  std::optional<InterfaceCoupling> coupling;  // interfaces: dg
  std::optional<ContactForces> contact;
  std::optional<BulkViscosity> bulk;  // bulk viscosity on the cells, when a coefficient is > 0
  std::optional<CentralDifference> run;

  const PolygonMesh& mesh() const { return bodies.mesh; }

 private:
  /// The internal force of the (varied) cell matrices; sets the two critical-step estimates.
  InternalForce make_force(const SplitDofMap& dofs, const CrackSites& sites);
  /// Each cell's dilatational speed (its stiffness factor's square root, if the material varies).
  std::vector<double> wave_speeds() const;
  /// The integrator with contact, boundaries, loads, cracks and its initial state.
  void make_integrator(InternalForce force, const SplitDofMap& dofs);
};

}  // namespace vorodg
