#pragma once
// A study scene run as `vorodg run` runs it, for every caller of the program's operations (the
// `run` and `merge` commands, the Python module, tests): the scene found by file or shipped name,
// the job-array shard set, the scene's kind (harness/StudyKind) run into the output folder, and
// the folder marked with the scene it holds (for `vorodg merge`).
#include <filesystem>
#include <string>

namespace vorodg {

struct SceneStudyOptions {
  std::string scene;  // a scene file, or the name of a shipped scene
  std::string out;    // the output folder (a rerun resumes there)
  int threads = 2;
  bool no_plots = false;
  bool quiet = false;
  bool force = false;  // dynamics: allow time.safety >= 1
  std::string shard;   // "K/N": run the tasks whose place is K modulo N (a job array)
};

/// Runs the study; returns the kind's exit code (0 done, 1 unexpected outcomes, 3 runs that broke
/// down). Throws InputError for a scene that does not exist or does not read.
int run_scene_study(const SceneStudyOptions& options);

/// A scene file, or the shipped scene of that name; throws InputError if neither exists.
std::filesystem::path resolve_scene(const std::string& name);

/// The shipped scenes' folder (data/scenes).
std::filesystem::path shipped_scenes_dir();

/// The file in an output folder that names the scene it was run from (for `vorodg merge`).
inline constexpr const char* kRunInfoFile = "run.json";

}  // namespace vorodg
