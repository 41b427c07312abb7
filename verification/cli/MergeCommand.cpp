#include "verification/cli/MergeCommand.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <set>
#include <vector>

#include "core/io/AtomicFile.hpp"
#include "core/util/Errors.hpp"
#include "verification/cli/CliSupport.hpp"
#include "verification/cli/RunCommand.hpp"
#include "verification/harness/Ensemble.hpp"

namespace vorodg {
namespace {

namespace fs = std::filesystem;

/// The run id of a complete results line, or "" for a line cut short by a stop.
std::string id_of(const std::string& line) {
  try {
    return nlohmann::json::parse(line).at("id").get<std::string>();
  } catch (const nlohmann::json::exception&) {
    return "";
  }
}

/// Gathers the shards' results files of `folder` into its results.jsonl; returns the number of
/// lines added.
int gather(const fs::path& folder) {
  std::vector<fs::path> shards;
  for (const auto& entry : fs::directory_iterator(folder))
    if (entry.is_regular_file() && Ensemble::is_shard_results(entry.path().filename().string()))
      shards.push_back(entry.path());
  if (shards.empty()) return 0;
  std::sort(shards.begin(), shards.end());
  std::string merged;
  std::set<std::string> ids;
  int added = 0;
  const auto take = [&](const fs::path& file, bool count) {
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);) {
      const std::string id = id_of(line);
      if (id.empty() || !ids.insert(id).second) continue;
      merged += line + "\n";
      added += count;
    }
  };
  take(folder / "results.jsonl", false);
  for (const fs::path& shard : shards) take(shard, true);
  write_file_atomically(folder / "results.jsonl", merged);
  return added;
}

}  // namespace

CLI::App* add_merge_command(CLI::App& app, MergeCommandOptions& o) {
  CLI::App* cmd = app.add_subcommand(
      "merge", "Gather the results of a study run as shards (--shard K/N) and write its reports");
  cmd->add_option("dir", o.dir, "The output folder the shards shared");
  cmd->add_flag("--no-plots", o.no_plots, "Skip the PNG plots");
  return cmd;
}

int run_merge_command(const MergeCommandOptions& o, const CLI::App& command) {
  if (o.dir.empty()) throw InputError("merge: expected the output folder of the shards");
  const fs::path dir = o.dir, info = dir / kRunInfoFile;
  if (!fs::is_regular_file(info))
    throw InputError("merge: '" + dir.string() + "' holds no " + kRunInfoFile +
                     ": expected the output folder of `vorodg run SCENE -o DIR --shard K/N`");
  echo_options("vorodg merge", command);
  std::string scene;
  try {
    scene = nlohmann::json::parse(std::ifstream(info)).at("scene").get<std::string>();
  } catch (const nlohmann::json::exception& e) {
    throw InputError("merge: " + info.string() + ": expected {\"scene\": path}: " + e.what());
  }
  int added = gather(dir);
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_directory()) added += gather(entry.path());
  std::cout << "merge: " << added << " results gathered from the shards\n";
  Ensemble::set_report_only(true);
  RunCommandOptions run;
  run.scene = scene;
  run.out = o.dir;
  run.threads = 1;
  run.no_plots = o.no_plots;
  run.quiet = true;
  return run_scene_study(run);
}

}  // namespace vorodg
