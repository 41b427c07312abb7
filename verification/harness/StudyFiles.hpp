#pragma once
// The files every study kind writes beside results.jsonl, in one layout: results.csv (one row per
// run, the columns of the kind's field table, in the plan's order) and summary.json, whose head
// is the same for every kind — the scene's name and the study kind at the top — followed by what
// the kind summarizes. Numbers that are not finite are written as records write them ("nan",
// "inf", "-inf"), never as a silent null. Both are written atomically.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/io/AtomicFile.hpp"
#include "verification/harness/RecordFields.hpp"

namespace vorodg {

/// {"scene": name, "study": kind}: what every summary.json starts with.
nlohmann::json summary_head(const std::string& scene, const std::string& study);

/// Writes `summary` as out/summary.json.
void write_summary(const std::filesystem::path& out, const nlohmann::json& summary);

/// Writes out/results.csv: the header of `fields`, then one row per record.
template <class Record>
void write_results_csv(const std::filesystem::path& out,
                       const std::vector<RecordField<Record>>& fields,
                       const std::vector<Record>& records) {
  std::string csv = csv_header(fields);
  for (const Record& r : records) csv += csv_row(fields, r);
  write_file_atomically(out / "results.csv", csv);
}

}  // namespace vorodg
