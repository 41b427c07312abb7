#pragma once
// `vorodg merge DIR`: the reports of a study run as shards (`vorodg run ... --shard K/N`). The
// shards' results files in DIR and its sub-folders are gathered into each folder's
// results.jsonl (a run already there keeps its line), then the study runs again in report-only
// mode: it writes every report as one process would have, and a run without a result is an
// error naming how many are missing, not a run.
#include <CLI/CLI.hpp>
#include <string>

namespace vorodg {

struct MergeCommandOptions {
  std::string dir;
  bool no_plots = false;
};

CLI::App* add_merge_command(CLI::App& app, MergeCommandOptions& options);
int run_merge_command(const MergeCommandOptions& options, const CLI::App& command);

}  // namespace vorodg
