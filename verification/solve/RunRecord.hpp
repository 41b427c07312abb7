#pragma once
// Typed records of runs: what a run is (StudyRun: a pure function of the scene), what it
// measured (RunMetrics, also `vorodg solve --metrics`) and both together (RunRecord: one line
// of results.jsonl). Each is a field table (RecordFields): JSON and results.csv are made from it,
// and read back through it; optional values are optional, never sentinels, and no number is read
// back out of a label.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Stopwatch.hpp"
#include "dg/DgElasticity.hpp"
#include "verification/harness/RecordFields.hpp"
#include "verification/solve/SolveRun.hpp"

namespace vorodg {

struct StudyRun {
  std::string id;  // unique and stable: mesh/level/realization/problem/nu/variant
  int mesh = 0, level = 0, realization = 0;  // indices into the scene
  std::string mesh_label;
  MeshFamily family = MeshFamily::rcp;
  double size = 0.0;  // d or h of the level
  std::uint64_t seed = 0;
  std::string problem;
  double nu = 0.0;
  int formulation = 0;            // index into the scene's formulations
  std::string formulation_name;   // cg, dg-al, ...
  std::string formulation_label;  // the scene's label of the formulation
  std::optional<double> kp;       // DG: this run's penalty
  std::string variant;            // label, plus " kp=..." for DG: for people, never parsed
};

struct RunMetrics {
  int cells = 0, vertices = 0, dofs = 0, free_dofs = 0;
  double h_avg = 0.0, l2_error = 0.0, energy_error = 0.0, rcond = 0.0;
  bool errors_measured = true;  // false: `solve --no-errors`; the record has no error keys
  long factor_nonzeros = 0;
  std::string solver = "cholmod";  // the one the run used: cholmod or amg-cg
  int solver_iterations = 0;       // amg-cg: CG iterations (cholmod: 0)
  double solver_residual = 0.0;    // amg-cg: ||b - A x|| / ||b|| (cholmod: 0)
  double max_divergence_defect = 0.0, min_moment_rcond = 0.0;
  StageTimes seconds;
  std::vector<std::string> shared_stages;  // stages made once for the mesh (SharedMeshWork)
  std::optional<DgReport> dg;              // DG only
  double peak_memory_mb = 0.0;

  int iterations() const { return dg ? dg->iterations : 1; }
  std::string stop_reason() const { return dg ? dg->stop_reason : "direct"; }
  double total_seconds() const;
};

/// The metrics of a finished solve on `mesh`.
RunMetrics run_metrics(const PolygonMesh& mesh, const SolveResult& result);

struct RunRecord {
  StudyRun run;
  std::optional<RunMetrics> metrics;  // none: the run broke down
  std::string error;                  // why it broke down

  bool ok() const { return metrics.has_value(); }
};

/// The field tables (harness/RecordFields): a run's metrics (metrics.json, and the part of a
/// record a finished run adds), and a whole record: its line of results.jsonl and its row of
/// results.csv.
const std::vector<RecordField<RunMetrics>>& metrics_fields();
const std::vector<RecordField<RunRecord>>& run_record_fields();

nlohmann::json to_json(const RunMetrics& metrics);
/// What `vorodg solve --metrics` writes (and the Python layer returns): the metrics, the problem,
/// the formulation, the mesh family, the penalty of a DG formulation and the BLAS in use.
nlohmann::json solve_record(const RunMetrics& metrics, const SolveSettings& settings,
                            MeshFamily family);
RunMetrics metrics_from_json(const nlohmann::json& value);
/// One line of results.jsonl.
nlohmann::json to_json(const RunRecord& record);
/// The outcome stored in a results.jsonl line, for the run the scene says it is. Throws
/// nlohmann::json::exception for a line that is not a record (it is then run again).
RunRecord record_from_json(const StudyRun& run, const nlohmann::json& line);

}  // namespace vorodg
