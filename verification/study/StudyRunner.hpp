#pragma once
// Runs a scene's ensemble: every (mesh, level, realization) is generated once and shared by all
// the (problem, material, formulation, k_p) runs on it; meshes run in parallel, each run on one
// thread, so results do not depend on the thread count. Each finished run is appended at once to
// results.jsonl; a run already there is skipped, so an interrupted study resumes.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "verification/study/Scene.hpp"

namespace vorodg {

struct StudyRun {
  std::string id;  // unique and stable: mesh/level/realization/problem/nu/variant
  int mesh = 0, level = 0, realization = 0;
  std::uint64_t seed = 0;
  std::string problem;
  double nu = 0.3;
  int formulation = 0;
  double kp = 0.0;      // 0 for CG
  std::string variant;  // formulation label (+ k_p)
};

/// Every run the scene asks for, in a fixed order.
std::vector<StudyRun> expand_runs(const Scene& scene);

struct StudyOptions {
  std::filesystem::path out;
  int threads = 2;
  bool progress = true;
};

/// Runs what results.jsonl in `out` does not hold yet and returns every result (old and new),
/// sorted by run id.
std::vector<nlohmann::json> run_study(const Scene& scene, const StudyOptions& options);

}  // namespace vorodg
