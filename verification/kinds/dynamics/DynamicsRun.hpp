#pragma once
// One run of a dynamics study: a mesh realization at one level, integrated by central differences
// with lumped masses and contact from t = 0 to the scene's end. Its history and its deformed-mesh
// series are written as it goes (atomically, so a stopped run leaves only whole files); what it
// measured becomes one record.
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dynamics/ExplicitSimulation.hpp"
#include "dynamics/problems/DynamicsProbe.hpp"
#include "verification/kinds/dynamics/DynamicsMesh.hpp"
#include "verification/kinds/dynamics/DynamicsScene.hpp"

namespace vorodg {

struct DynamicsRecord {
  EnsembleRunId run;
  int cells = 0, dofs = 0;
  double h_avg = 0.0;
  double dt = 0.0;
  double dt_lanczos = 0.0, dt_cells = 0.0;  // the two estimates of the critical step
  int lanczos_iterations = 0;
  long steps = 0;
  double end_time = 0.0;
  double contact_stiffness = NAN;  // a fixed displacement penalty (NaN: mass-scaled)
  DynamicsMeasures measures;
  bool complete = false;
  std::string failure;
  double seconds = 0.0;
  double loop_seconds = 0.0;        // of which the time loop
  int checkpoints = 0;              // written by this process (a resumed run: since it resumed)
  double checkpoint_seconds = 0.0;  // of which writing them
};

/// Builds the bodies' mesh of the first realization of every level, so that a mesh spec the
/// bodies cannot carry is refused as bad input (naming the mesh block) before anything runs.
void check_dynamics_meshes(const DynamicsScene& scene, const std::vector<EnsembleRunId>& runs);

/// The simulation of realization `id` of `scene`: its bodies' mesh, the scene's physics and its
/// problem's loads (the scene must outlive it). Throws InputError for what the mesh cannot carry.
ExplicitSimulation dynamics_simulation(const DynamicsScene& scene, const EnsembleRunId& id);

/// Runs one realization, writing history/<id>.csv and (outputs.vtu) vtu/<id>.pvd under `out`.
/// A run that becomes unstable or breaks down numerically stops there: it keeps its history and
/// is recorded incomplete with the reason.
/// `at_end`, if given, sees the simulation after the run (its state, its cracks): what the Python
/// layer reads the fragments from.
DynamicsRecord run_dynamics(const DynamicsScene& scene, const EnsembleRunId& run,
                            const std::filesystem::path& out,
                            const std::function<void(const ExplicitSimulation&)>& at_end = {});

/// A record's line of results.jsonl.
nlohmann::json dynamics_record_json(const DynamicsScene& scene, const DynamicsRecord& record);

}  // namespace vorodg
