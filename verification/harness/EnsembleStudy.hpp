#pragma once
// The loop every ensemble study kind shares (fracture, dynamics, fragmentation): its runs go
// through the resumable pool (EnsembleRun), each run's failure becomes its record's, a result
// that is not finite makes the run incomplete, and every record (old and new) is read back
// through the kind's field table for the reports. A kind gives what one run does and its
// progress line.
#include <exception>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/util/Errors.hpp"
#include "verification/harness/EnsembleRun.hpp"
#include "verification/harness/RecordFields.hpp"

namespace vorodg {

template <class Record>
struct StudyRecords {
  std::vector<Record> records;  // in the order of the runs (on the process that reports)
  int incomplete = 0;
};

template <class Record>
StudyRecords<Record> run_study_records(
    const std::vector<SceneMesh>& meshes, const std::filesystem::path& out, int threads,
    bool progress, const std::vector<RecordField<Record>>& fields,
    const std::function<Record(const EnsembleRunId&)>& run_one,
    const std::function<std::string(const Record&)>& progress_line) {
  const std::vector<EnsembleRunId> runs = ensemble_runs(meshes);
  const auto execute = [&](const EnsembleRunId& id) {
    Record r;
    try {
      r = run_one(id);
    } catch (const Interrupted&) {  // stopped on request and checkpointed: no record, it resumes
      throw;
    } catch (const std::exception& e) {  // recorded and reported, not fatal to the study
      r = Record{};
      r.run = id;
      r.failure = e.what();
    }
    refuse_non_finite(fields, r);
    return RunOutcome{record_json(fields, r), progress_line(r)};
  };
  const std::vector<nlohmann::json> done =
      run_ensemble(meshes, runs, out, threads, progress, execute);
  StudyRecords<Record> result;
  for (std::size_t i = 0; i < done.size(); ++i) {
    Record r;
    r.run = runs[i];
    try {
      read_record(fields, done[i], r);
    } catch (const nlohmann::json::exception& e) {  // written by another version of vorodg
      throw InputError((out / "results.jsonl").string() + ": the record of " + runs[i].id() +
                       " is not one this version reads (" + e.what() +
                       "); remove its line to run it again");
    }
    refuse_non_finite(fields, r);  // a record resumed from an older run too
    result.records.push_back(r);
    if (!r.complete) ++result.incomplete;
  }
  return result;
}

}  // namespace vorodg
