#include "verification/model/RunRecord.hpp"

#include <cmath>

#include "core/util/PeakMemory.hpp"
#include "verification/model/Choices.hpp"

namespace vorodg {
namespace {

using nlohmann::json;

/// A number of a record; NaN where it is null (JSON has no NaN: a non-finite value written to
/// results.jsonl comes back as null).
double number(const json& value, const char* key) {
  const json& v = value.at(key);
  return v.is_number() ? v.get<double>() : std::nan("");
}

}  // namespace

double RunMetrics::total_seconds() const {
  double total = 0.0;
  for (const auto& [stage, s] : seconds) total += s;
  return total;
}

RunMetrics run_metrics(const PolygonMesh& mesh, const SolveResult& r) {
  return {.cells = mesh.num_cells(),
          .vertices = mesh.num_vertices(),
          .dofs = r.dofs,
          .free_dofs = r.free_dofs,
          .h_avg = mesh.h_avg(),
          .l2_error = r.l2_error,
          .energy_error = r.energy_error,
          .rcond = r.rcond,
          .errors_measured = r.errors_measured,
          .factor_nonzeros = r.factor_nonzeros,
          .solver = solver_name(r.solver),
          .solver_iterations = r.amg.iterations,
          .solver_residual = r.amg.relative_residual,
          .max_divergence_defect = r.max_divergence_defect,
          .min_moment_rcond = r.min_moment_rcond,
          .seconds = r.seconds,
          .shared_stages = r.shared_stages,
          .dg = r.dg,
          .peak_memory_mb = peak_memory_mb()};  // of the whole process so far
}

json to_json(const RunMetrics& m) {
  json j = {{"cells", m.cells},
            {"vertices", m.vertices},
            {"dofs", m.dofs},
            {"free_dofs", m.free_dofs},
            {"h_avg", m.h_avg},
            {"rcond", m.rcond},
            {"factor_nonzeros", m.factor_nonzeros},
            {"solver", m.solver},
            {"solver_iterations", m.solver_iterations},
            {"solver_residual", m.solver_residual},
            {"max_divergence_defect", m.max_divergence_defect},
            {"min_moment_rcond", m.min_moment_rcond},
            {"iterations", m.iterations()},
            {"stop_reason", m.stop_reason()},
            {"relative_gap", m.dg ? m.dg->relative_gap : 0.0},
            {"seconds", json(m.seconds)},
            {"shared_stages", m.shared_stages},
            {"peak_memory_mb", m.peak_memory_mb}};
  if (m.errors_measured) {  // absent, not null: null stands for a non-finite error
    j["l2_error"] = m.l2_error;
    j["energy_error"] = m.energy_error;
  }
  if (m.dg) {  // DG only: the presence of "penalty" says a record is DG
    j["penalty"] = m.dg->penalty;
    j["last_change"] = m.dg->last_change;
    j["gap_norm"] = m.dg->gap_norm;
    j["seconds_per_iteration"] = m.dg->seconds_per_iteration;
  }
  return j;
}

RunMetrics metrics_from_json(const json& j) {
  RunMetrics m;
  m.cells = j.at("cells").get<int>();
  m.vertices = j.at("vertices").get<int>();
  m.dofs = j.at("dofs").get<int>();
  m.free_dofs = j.at("free_dofs").get<int>();
  m.h_avg = number(j, "h_avg");
  m.errors_measured = j.contains("l2_error");
  if (m.errors_measured) {
    m.l2_error = number(j, "l2_error");
    m.energy_error = number(j, "energy_error");
  }
  m.rcond = number(j, "rcond");
  m.factor_nonzeros = j.at("factor_nonzeros").get<long>();
  m.solver = j.value("solver", "cholmod");  // records from before amg-cg existed
  m.solver_iterations = j.value("solver_iterations", 0);
  m.solver_residual = j.value("solver_residual", 0.0);
  m.max_divergence_defect = number(j, "max_divergence_defect");
  m.min_moment_rcond = number(j, "min_moment_rcond");
  m.seconds = j.at("seconds").get<StageTimes>();
  m.shared_stages = j.value("shared_stages", std::vector<std::string>{});  // older records: none
  m.peak_memory_mb = number(j, "peak_memory_mb");
  if (j.contains("penalty")) {
    const json& d = j;
    DgReport dg;
    dg.iterations = j.at("iterations").get<int>();
    dg.stop_reason = j.at("stop_reason").get<std::string>();
    dg.relative_gap = number(j, "relative_gap");
    dg.penalty = number(d, "penalty");
    dg.last_change = number(d, "last_change");
    dg.gap_norm = number(d, "gap_norm");
    dg.seconds_per_iteration = number(d, "seconds_per_iteration");
    m.dg = dg;
  }
  return m;
}

json to_json(const RunRecord& record) {
  const StudyRun& r = record.run;
  json j = {{"id", r.id},
            {"mesh", r.mesh_label},
            {"family", std::string(family_name(r.family))},
            {"level", r.level},
            {"size", r.size},
            {"realization", r.realization},
            {"seed", r.seed},
            {"problem", r.problem},
            {"nu", r.nu},
            {"formulation", r.formulation_name},
            {"label", r.formulation_label},
            {"variant", r.variant},
            {"status", record.ok() ? "ok" : "failed"}};
  if (r.kp) j["kp"] = *r.kp;
  if (!record.ok()) j["error"] = record.error;
  if (record.metrics) j.update(to_json(*record.metrics));
  return j;
}

RunRecord record_from_json(const StudyRun& run, const json& line) {
  RunRecord record{run, std::nullopt, ""};
  if (line.at("id").get<std::string>() != run.id) throw json::other_error::create(501, "id", &line);
  if (line.at("status").get<std::string>() == "ok")
    record.metrics = metrics_from_json(line);
  else
    record.error = line.at("error").get<std::string>();
  return record;
}

}  // namespace vorodg
