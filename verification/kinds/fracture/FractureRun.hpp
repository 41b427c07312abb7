#pragma once
// One run of a fracture study: a mesh realization at one level, followed along the load path.
// Its curve, its crack faces and its deformed-mesh series are written as it goes (curves and
// .vtu atomically, so a stopped run leaves only whole files); its summary becomes one record.
#include <cmath>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/meshgen/MeshFamily.hpp"
#include "verification/harness/EnsembleRun.hpp"
#include "verification/kinds/fracture/FractureScene.hpp"

namespace vorodg {

class CohesiveFracture;
struct PathPoint;
struct InterfacePoint;

struct FractureRecord {
  EnsembleRunId run;
  int cells = 0, dofs = 0, full_dg_dofs = 0;
  double h_avg = 0.0;
  double peak_load = 0.0, displacement_at_peak = 0.0;
  /// The load where the stroke first reaches twice the peak's after the peak (interpolated
  /// between the path's points): the softening branch's level; NaN if the path ends before.
  double load_at_twice_peak = NAN;
  double dissipated_energy = 0.0, crack_length = 0.0;
  /// The cracked faces' total length over their extent along y at the end (the straight crack
  /// of both problems runs along y): 1 for a straight crack, more for a winding or branched one;
  /// NaN without cracked faces.
  double crack_tortuosity = NAN;
  double energy_balance_error = 0.0;  // the largest over the converged points
  double closed_form_error = NAN;     // tension bar: the largest deviation from the closed form
  int points = 0, newton_iterations = 0, factorizations = 0;
  bool complete = false;
  std::string failure;
  std::string ended;  // why a complete run ended before its end point (QuasiStaticPath)
  double seconds = 0.0;
  double path_seconds = 0.0;  // of which following the path (after mesh, element and setup)
};

/// The mesh of one run (generated and validated): what the dynamic three-point bend of the same
/// family, size, seed and realization meshes too.
GeneratedMesh fracture_run_mesh(const FractureScene& scene, const EnsembleRunId& run);

/// Builds the first realization of every mesh level and its fracture setup, so that a scene
/// whose geometry the meshes cannot carry (no vertex at the load point, no edges along the crack
/// line) is refused as bad input before anything runs or is written.
void check_fracture_meshes(const FractureScene& scene, const std::vector<EnsembleRunId>& runs);

/// Runs one realization, writing curves/<id>.csv, cracks/<id>.csv and vtu/<id>.pvd under `out`.
FractureRecord run_fracture(const FractureScene& scene, const EnsembleRunId& run,
                            const std::filesystem::path& out,
                            const FracturePathObserver& observe = {});

/// A record's line of results.jsonl.
nlohmann::json fracture_record_json(const FractureRecord& record);
/// The fields of a record that are numbers: the quantities `statistics.quantities` may name.
std::vector<std::string> fracture_record_numbers();

}  // namespace vorodg
