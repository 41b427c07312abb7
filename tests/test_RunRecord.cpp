// The static run record on its field table (verification/solve/RunRecord, harness/RecordFields):
//   - a DG record with every field set comes back from its JSON line field for field;
//   - non-finite numbers (an overflowed error, a NaN condition estimate) come back as they were,
//     and a line written by an older version (null for a non-finite number, no solver, no
//     shared stages) reads back with the defaults;
//   - a failed run's line has its error and no metrics, and reads back failed;
//   - results.csv: every row has the header's number of cells, texts with commas or double
//     quotes are quoted (their quotes turned to '), a CG run leaves kp empty.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "verification/solve/RunRecord.hpp"

namespace vorodg {
namespace {

using nlohmann::json;

StudyRun dg_run() {
  StudyRun r;
  r.id = "rcp-L1-R0/beam/nu=0.3/dg-nitsche kp=1000";
  r.mesh_label = "rcp";
  r.level = 1;
  r.size = 0.125;
  r.seed = 42;
  r.problem = "beam";
  r.nu = 0.3;
  r.formulation_name = "dg-nitsche";
  r.formulation_label = "dg-nitsche";
  r.kp = 1000.0;
  r.variant = "dg-nitsche kp=1000";
  return r;
}

RunMetrics dg_metrics() {
  RunMetrics m;
  m.cells = 100, m.vertices = 210, m.dofs = 1200, m.free_dofs = 1180;
  m.h_avg = 0.1234, m.l2_error = 1.5e-3, m.energy_error = 2.5e-2, m.rcond = 1e-9;
  m.factor_nonzeros = 98765;
  m.solver = "cholmod";
  m.max_divergence_defect = 1e-15, m.min_moment_rcond = 0.01;
  m.seconds = {{"assemble", 0.5}, {"solve", 0.25}};
  m.shared_stages = {"mesh"};
  m.peak_memory_mb = 123.0;
  m.dg = DgReport{17, "converged", 1e-11, 2e-4, 3e-5, 1.5e5, 0.01};
  return m;
}

TEST(RunRecord, ADgRecordComesBackFieldForField) {
  const RunRecord record{dg_run(), dg_metrics(), ""};
  const RunRecord back = record_from_json(record.run, json::parse(to_json(record).dump()));
  ASSERT_TRUE(back.ok());
  const RunMetrics &a = *record.metrics, &b = *back.metrics;
  EXPECT_EQ(b.cells, a.cells);
  EXPECT_EQ(b.vertices, a.vertices);
  EXPECT_EQ(b.free_dofs, a.free_dofs);
  EXPECT_EQ(b.h_avg, a.h_avg);
  EXPECT_EQ(b.l2_error, a.l2_error);
  EXPECT_EQ(b.energy_error, a.energy_error);
  EXPECT_TRUE(b.errors_measured);
  EXPECT_EQ(b.factor_nonzeros, a.factor_nonzeros);
  EXPECT_EQ(b.seconds, a.seconds);
  EXPECT_EQ(b.shared_stages, a.shared_stages);
  ASSERT_TRUE(b.dg);
  EXPECT_EQ(b.dg->iterations, 17);
  EXPECT_EQ(b.dg->stop_reason, "converged");
  EXPECT_EQ(b.dg->relative_gap, 3e-5);
  EXPECT_EQ(b.dg->penalty, 1.5e5);
  EXPECT_EQ(b.dg->gap_norm, 2e-4);
  EXPECT_EQ(b.dg->seconds_per_iteration, 0.01);
}

TEST(RunRecord, NonFiniteNumbersComeBackAsTheyWere) {
  RunRecord record{dg_run(), dg_metrics(), ""};
  record.metrics->l2_error = std::numeric_limits<double>::infinity();
  record.metrics->rcond = std::nan("");
  const json line = json::parse(to_json(record).dump());
  const RunRecord back = record_from_json(record.run, line);
  EXPECT_TRUE(std::isinf(back.metrics->l2_error));
  EXPECT_TRUE(std::isnan(back.metrics->rcond));
  // An older line: null for a non-finite number, no solver, no shared stages, CG.
  json old = line;
  old["rcond"] = nullptr;
  for (const char* key : {"solver", "solver_iterations", "solver_residual", "shared_stages",
                          "penalty", "last_change", "gap_norm", "seconds_per_iteration"})
    old.erase(key);
  const RunRecord older = record_from_json(record.run, old);
  EXPECT_TRUE(std::isnan(older.metrics->rcond));
  EXPECT_EQ(older.metrics->solver, "cholmod");
  EXPECT_TRUE(older.metrics->shared_stages.empty());
  EXPECT_FALSE(older.metrics->dg);  // no penalty: a CG record
  old.erase("cells");
  EXPECT_THROW(record_from_json(record.run, old), json::exception);
}

TEST(RunRecord, AFailedRunKeepsItsErrorAndNoMetrics) {
  const RunRecord failed{dg_run(), std::nullopt, "not positive definite"};
  const json line = to_json(failed);
  EXPECT_EQ(line.at("status"), "failed");
  EXPECT_EQ(line.at("error"), "not positive definite");
  EXPECT_FALSE(line.contains("cells"));
  EXPECT_FALSE(line.contains("l2_error"));
  const RunRecord back = record_from_json(failed.run, line);
  EXPECT_FALSE(back.ok());
  EXPECT_EQ(back.error, "not positive definite");
  EXPECT_FALSE(to_json(RunRecord{dg_run(), dg_metrics(), ""}).contains("error"));
}

TEST(RunRecord, CsvRowsHaveTheHeadersCellsAndQuotedTexts) {
  const auto& fields = run_record_fields();
  const std::string header = csv_header(fields);
  const auto cells = [](const std::string& line) {
    return std::count(line.begin(), line.end(), ',') + 1;  // no quoted text here holds a comma
  };
  StudyRun cg = dg_run();
  cg.id = "quad-L0-R0/beam/nu=0.3/cg";
  cg.kp.reset();
  cg.formulation_name = "cg";
  cg.variant = "cg \"plain\"";
  RunMetrics m = dg_metrics();
  m.dg.reset();
  const std::string ok = csv_row(fields, RunRecord{cg, m, ""});
  const std::string failed = csv_row(fields, RunRecord{cg, std::nullopt, "singular"});
  EXPECT_EQ(cells(ok), cells(header));
  EXPECT_EQ(cells(failed), cells(header));
  EXPECT_NE(ok.find("\"cg 'plain'\""), std::string::npos) << ok;
  EXPECT_NE(ok.find(",cg,\"cg 'plain'\",,ok,"), std::string::npos) << ok;  // no kp
  EXPECT_NE(failed.find(",failed,,,,,,,,,,,\"singular\""), std::string::npos) << failed;
}

}  // namespace
}  // namespace vorodg
