#pragma once
// From a study's records to what a researcher reads: results.csv (one row per run),
// summary.json (the statistics of StudySummary), timings.json, convergence.csv and the
// convergence tables (ConvergenceTable: console text and Markdown from the same data), the
// rate-against-k_p trend and each rate beside the published one; a kind adds its own sections
// (the patch-suite verdicts, the penalty analysis, the trade-off) without the report naming it.
#include <filesystem>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "verification/solve/RunRecord.hpp"
#include "verification/static/Scene.hpp"
#include "verification/static/StudySummary.hpp"

namespace vorodg {

struct StudyReport {
  std::string markdown;  // report.md without its pictures (they are drawn afterwards)
  int unexpected = 0;    // outcomes that differ from the expected ones (a patch suite's)
};

/// What a static kind's report sections read: the scene, the statistics, every record and the
/// output folder.
struct ReportInput {
  const Scene& scene;
  const StudySummary& summary;
  const std::vector<RunRecord>& records;
  const std::filesystem::path& out;
};

/// The sections a static kind adds after the report's header: they write into `md` (and their
/// own files into in.out) and return the number of outcomes other than the expected ones.
using ReportSections = std::function<int(const ReportInput& in, std::ostringstream& md)>;

/// The convergence tables of every group (printed, in report.md and in convergence.csv) and the
/// rate-against-k_p trend: what every static kind but the patch suite shows.
int convergence_sections(const ReportInput& in, std::ostringstream& md);

/// Writes results.csv, summary.json and timings.json into `out` (atomically), then the kind's
/// sections, and returns the report's text.
StudyReport write_study_report(const Scene& scene, const std::vector<RunRecord>& records,
                               const std::filesystem::path& out,
                               const ReportSections& sections = convergence_sections);

/// Appends a link to each of `pictures` that exists in `out`, then writes `out`/report.md.
void finish_report_markdown(std::string markdown, const std::filesystem::path& out,
                            const std::vector<std::string>& pictures);

/// The pictures the plots of a study kind may draw, in the order report.md shows them.
std::vector<std::string> study_pictures();

}  // namespace vorodg
