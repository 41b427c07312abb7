#pragma once
// A dynamics study: every (mesh, level, realization) of the scene is one run (DynamicsRun), runs
// go in parallel (each on one thread) and each finished one is appended at once to
// results.jsonl, so an interrupted study resumes where it stopped. The reports are written from
// the records: results.csv (one row per run), summary.json and report.md, with every measured
// figure beside its theory (docs/dynamics.md "The dynamics study").
#include <filesystem>
#include <vector>

#include "verification/dynamics/DynamicsRun.hpp"
#include "verification/harness/EnsembleStudy.hpp"

namespace vorodg {

using DynamicsStudyResult = StudyRecords<DynamicsRecord>;

/// Runs what results.jsonl in `out` does not hold yet; writes the reports; returns every record.
DynamicsStudyResult run_dynamics_study(const DynamicsScene& scene, const std::filesystem::path& out,
                                       int threads, bool progress);

}  // namespace vorodg
