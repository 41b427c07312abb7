#pragma once
// A fracture study: every (mesh, level, realization) of the scene is one run (FractureRun),
// runs go in parallel (each on one thread) and each finished one is appended at once to
// results.jsonl, so an interrupted study resumes where it stopped. The reports are written from
// the records: results.csv (one row per run), summary.json and report.md with, per level, the
// statistics of peak load, dissipated energy and crack length, and the two-sample
// Kolmogorov-Smirnov distance between successive levels (docs/fracture.md "Statistics").
#include <filesystem>
#include <vector>

#include "verification/fracture/FractureRun.hpp"
#include "verification/harness/EnsembleStudy.hpp"

namespace vorodg {

using FractureStudyResult = StudyRecords<FractureRecord>;

/// Runs what results.jsonl in `out` does not hold yet; writes the reports; returns every record.
FractureStudyResult run_fracture_study(const FractureScene& scene, const std::filesystem::path& out,
                                       int threads, bool progress);

}  // namespace vorodg
