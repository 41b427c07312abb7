#include "verification/solve/RunRecord.hpp"

#include <cmath>

#include <type_traits>
#include "core/util/BlasInfo.hpp"
#include "core/util/PeakMemory.hpp"

#include "verification/model/Choices.hpp"

namespace vorodg {

using nlohmann::json;

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

namespace {

using M = RunMetrics;
const CsvFormat kExact{true, 17, false};  // results.csv: numbers that read back exactly

/// A member of the DG report, present with it.
template <class T>
RecordField<M> dg_field(const std::string& name, T DgReport::*member, CsvFormat csv = kNotInCsv) {
  RecordField<M> f{name,
                   [member](const M& m) {
                     if constexpr (std::is_same_v<T, double>)
                       return number_json((*m.dg).*member);
                     else
                       return json((*m.dg).*member);
                   },
                   [member](M& m, const json& j) {
                     if constexpr (std::is_same_v<T, double>)
                       (*m.dg).*member = read_number(j);
                     else
                       (*m.dg).*member = j.get<T>();
                   },
                   csv};
  f.when = [](const M& m) { return m.dg.has_value(); };
  return f;
}

/// Read back only where the record is DG (metrics_from_json makes the report first).
template <class T>
void set_dg(M& m, T DgReport::*member, const json& j) {
  if (!m.dg) return;
  if constexpr (std::is_same_v<T, double>)
    (*m.dg).*member = read_number(j);
  else
    (*m.dg).*member = j.get<T>();
}

std::vector<RecordField<M>> make_metrics_fields() {
  std::vector<RecordField<M>> f = {
      dg_field("penalty", &DgReport::penalty),  // its presence says a record is DG
      field("cells", &M::cells),
      field("dofs", &M::dofs),
      field("h_avg", &M::h_avg, kExact),
      field("l2_error", &M::l2_error, kExact),
      field("energy_error", &M::energy_error, kExact),
      field("rcond", &M::rcond, kExact),
      {"iterations", [](const M& m) { return json(m.iterations()); },
       [](M& m, const json& j) { set_dg(m, &DgReport::iterations, j); }},
      {"stop_reason", [](const M& m) { return json(m.stop_reason()); },
       [](M& m, const json& j) { set_dg(m, &DgReport::stop_reason, j); }},
      {"relative_gap", [](const M& m) { return number_json(m.dg ? m.dg->relative_gap : 0.0); },
       [](M& m, const json& j) { set_dg(m, &DgReport::relative_gap, j); }, kExact},
      {"seconds_total", [](const M& m) { return number_json(m.total_seconds()); }, nullptr, kExact,
       false, false},
      field("vertices", &M::vertices, kNotInCsv),
      field("free_dofs", &M::free_dofs, kNotInCsv),
      field("factor_nonzeros", &M::factor_nonzeros, kNotInCsv),
      field("solver", &M::solver, kNotInCsv),  // older records: cholmod, before amg-cg existed
      field("solver_iterations", &M::solver_iterations, kNotInCsv),
      field("solver_residual", &M::solver_residual, kNotInCsv),
      field("max_divergence_defect", &M::max_divergence_defect, kNotInCsv),
      field("min_moment_rcond", &M::min_moment_rcond, kNotInCsv),
      field("seconds", &M::seconds, kNotInCsv),
      field("shared_stages", &M::shared_stages, kNotInCsv),  // older records: none
      field("peak_memory_mb", &M::peak_memory_mb, kNotInCsv),
      dg_field("last_change", &DgReport::last_change),
      dg_field("gap_norm", &DgReport::gap_norm),
      dg_field("seconds_per_iteration", &DgReport::seconds_per_iteration)};
  for (RecordField<M>& x : f) {
    if (x.name == "l2_error" || x.name == "energy_error")  // absent, not NaN, when not measured
      x.when = [](const M& m) { return m.errors_measured; };
    if (x.name == "solver" || x.name.starts_with("solver_") || x.name == "shared_stages")
      x.required = false;
  }
  return f;
}

using R = RunRecord;

/// A field of the run's metrics as a field of its record: present where the run finished.
RecordField<R> metrics_field(const RecordField<M>& f) {
  RecordField<R> out{f.name,     [get = f.get](const R& r) { return get(*r.metrics); },
                     nullptr,    f.csv,
                     f.optional, f.in_json,
                     f.number};
  out.when = [holds = f.when](const R& r) { return r.ok() && (!holds || holds(*r.metrics)); };
  return out;
}

std::vector<RecordField<R>> make_record_fields() {
  const CsvFormat quoted{true, 6, false, true};
  std::vector<RecordField<R>> f = {
      {"id", [](const R& r) { return json(r.run.id); }, nullptr, quoted},
      {"mesh", [](const R& r) { return json(r.run.mesh_label); }},
      {"family", [](const R& r) { return json(std::string(family_name(r.run.family))); }},
      {"level", [](const R& r) { return json(r.run.level); }},
      {"size", [](const R& r) { return number_json(r.run.size); }, nullptr, kExact},
      {"realization", [](const R& r) { return json(r.run.realization); }},
      {"seed", [](const R& r) { return json(r.run.seed); }},
      {"problem", [](const R& r) { return json(r.run.problem); }},
      {"nu", [](const R& r) { return number_json(r.run.nu); }, nullptr, kExact},
      {"formulation", [](const R& r) { return json(r.run.formulation_name); }},
      {"label", [](const R& r) { return json(r.run.formulation_label); }, nullptr, kNotInCsv},
      {"variant", [](const R& r) { return json(r.run.variant); }, nullptr, quoted},
      {"kp", [](const R& r) { return number_json(r.run.kp.value_or(0.0)); }, nullptr, kExact},
      {"status", [](const R& r) { return json(r.ok() ? "ok" : "failed"); }}};
  f[f.size() - 2].when = [](const R& r) { return r.run.kp.has_value(); };  // DG runs only
  for (const RecordField<M>& m : metrics_fields()) f.push_back(metrics_field(m));
  RecordField<R> error{"error", [](const R& r) { return json(r.error); }, nullptr, kNotInCsv};
  error.when = [](const R& r) { return !r.ok(); };
  f.push_back(error);
  f.push_back({"error", [](const R& r) { return json(r.error); }, nullptr, quoted, false, false});
  return f;
}

}  // namespace

const std::vector<RecordField<RunMetrics>>& metrics_fields() {
  static const std::vector<RecordField<RunMetrics>> fields = make_metrics_fields();
  return fields;
}

const std::vector<RecordField<RunRecord>>& run_record_fields() {
  static const std::vector<RecordField<RunRecord>> fields = make_record_fields();
  return fields;
}

json to_json(const RunMetrics& m) {
  return record_json(metrics_fields(), m);
}

RunMetrics metrics_from_json(const json& j) {
  RunMetrics m;
  // What a record is decides which of its fields exist: DG by "penalty", measured errors by
  // "l2_error".
  m.errors_measured = j.contains("l2_error");
  if (j.contains("penalty")) m.dg.emplace();
  read_record(metrics_fields(), j, m);
  return m;
}

json to_json(const RunRecord& record) {
  return record_json(run_record_fields(), record);
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

nlohmann::json solve_record(const RunMetrics& metrics, const SolveSettings& settings,
                            MeshFamily family) {
  nlohmann::json json = to_json(metrics);
  json["problem"] = settings.problem;
  json["formulation"] = settings.formulation;
  json["family"] = family_name(family);
  if (metrics.dg) {
    json["kp"] = penalty_multiplier(dg_options(settings));
    json["penalty_scaling"] = penalty_name(penalty_scaling(dg_options(settings)));
  }
  json["blas"] = blas_description();
  return json;
}

}  // namespace vorodg
