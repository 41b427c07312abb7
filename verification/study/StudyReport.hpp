#pragma once
// From a study's records to what a researcher reads: results.csv (one row per run),
// summary.json (the statistics of StudySummary), timings.json, convergence.csv and the
// convergence tables (ConvergenceTable: console text and Markdown from the same data), the
// patch-suite verdicts, the rate-against-k_p trend and each rate beside the published one.
#include <filesystem>
#include <string>
#include <vector>

#include "verification/solve/RunRecord.hpp"
#include "verification/study/Scene.hpp"

namespace vorodg {

struct StudyReport {
  std::string markdown;  // report.md without its pictures (they are drawn afterwards)
  int unexpected = 0;    // patch-suite outcomes that differ from the expected ones
};

/// Writes results.csv, summary.json, timings.json and convergence.csv into `out` (atomically),
/// prints the tables and returns the report's text.
StudyReport write_study_report(const Scene& scene, const std::vector<RunRecord>& records,
                               const std::filesystem::path& out);

/// Appends a link to each of `pictures` that exists in `out`, then writes `out`/report.md.
void finish_report_markdown(std::string markdown, const std::filesystem::path& out,
                            const std::vector<std::string>& pictures);

/// The pictures the plots of a study kind may draw, in the order report.md shows them.
std::vector<std::string> study_pictures();

}  // namespace vorodg
