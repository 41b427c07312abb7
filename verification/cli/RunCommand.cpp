#include "verification/cli/RunCommand.hpp"

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>

#include "core/io/AtomicFile.hpp"
#include "core/util/Errors.hpp"
#include "core/util/StopRequest.hpp"
#include "verification/api/SceneStudy.hpp"
#include "verification/cli/CliSupport.hpp"
#include "verification/harness/Ensemble.hpp"
#include "verification/harness/StudyKind.hpp"
#include "verification/model/Choices.hpp"

namespace vorodg {
namespace {

namespace fs = std::filesystem;

int list_scenes() {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(shipped_scenes_dir()))
    if (e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::size_t width = 0;
  for (const fs::path& f : files) width = std::max(width, f.stem().string().size());
  for (const fs::path& f : files) {
    const std::string text = read_file(f);
    const StudyKind& kind = scene_kind(text, f.string());
    std::cout << std::left << std::setw(static_cast<int>(width + 2)) << f.stem().string()
              << kind.name << ": " << kind.read(text, f.string()) << "\n";
  }
  return 0;
}

}  // namespace

CLI::App* add_run_command(CLI::App& app, RunCommandOptions& o) {
  CLI::App* cmd = app.add_subcommand("run", "Run a study scene and write its report");
  cmd->add_option("scene", o.scene, "Scene file (.json) or the name of a shipped scene");
  cmd->add_option("-o,--output", o.out, "Output folder (created; a rerun resumes)");
  cmd->add_option("--threads", o.threads, "Runs in parallel")->capture_default_str();
  cmd->add_flag("--list", o.list, "List the shipped scenes");
  cmd->add_option("--keys", o.keys,
                  "Print every key of a study kind (" + choice_alternatives(study_choices()) +
                      "): type, default, range, meaning");
  cmd->add_flag("--no-plots", o.no_plots, "Skip the PNG plots");
  cmd->add_flag("--quiet", o.quiet, "No progress bar");
  cmd->add_option("--shard", o.shard,
                  "K/N: run only the tasks whose place is K modulo N, into their own results "
                  "file (a job array without MPI; then `vorodg merge DIR`)");
  cmd->add_flag("--force", o.force,
                "Dynamics scenes: allow time.safety >= 1 (a step at or above the critical one)");
  return cmd;
}

int run_run_command(const RunCommandOptions& o, const CLI::App& command) {
  if (o.list) return list_scenes();
  if (!o.keys.empty()) {
    std::cout << key_table_markdown(study_kind(o.keys, "--keys: "));
    return 0;
  }
  if (o.scene.empty())
    throw InputError("run: expected a scene (a file or a shipped name; see --list)");
  if (o.out.empty()) throw InputError("run: expected an output folder (-o DIR)");
  if (o.threads < 1) throw InputError("--threads " + std::to_string(o.threads) + ": expected >= 1");
  echo_options("vorodg run", command);
  // SIGTERM / SIGINT: every run in flight checkpoints and the study ends with kExitInterrupted.
  install_stop_handlers();
  return run_scene_study(o);
}

}  // namespace vorodg
