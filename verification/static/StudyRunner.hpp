#pragma once
// Runs a scene's ensemble: every (mesh, level, realization) is generated once and shared by all
// the (problem, material, formulation, k_p) runs on it; meshes run in parallel, each run on one
// thread, so results do not depend on the thread count. Each finished run is appended at once to
// results.jsonl; a run already there is skipped, so an interrupted study resumes.
#include <filesystem>
#include <vector>

#include "verification/solve/RunRecord.hpp"
#include "verification/static/Scene.hpp"

namespace vorodg {

/// Every run the scene asks for, in a fixed order. Throws InputError if two runs share an id.
std::vector<StudyRun> expand_runs(const Scene& scene);

/// The settings of one run: the formulation's, with the run's problem, material and k_p.
SolveSettings run_settings(const Scene& scene, const StudyRun& run);

struct StudyOptions {
  std::filesystem::path out;
  int threads = 2;
  bool progress = true;
};

/// Runs what results.jsonl in `out` does not hold yet and returns every record (old and new),
/// in the order of expand_runs.
std::vector<RunRecord> run_study(const Scene& scene, const StudyOptions& options);

}  // namespace vorodg
