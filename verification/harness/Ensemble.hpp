#pragma once
// The processes that share one study: this process alone, or the ranks of an MPI job started by
// mpirun (or srun). Rank 0 is the coordinator: it hands out the tasks (TaskPool), is the only
// writer of results.jsonl, and writes the reports; the other ranks run tasks and report back.
//
// A build without MPI (-DVORODG_MPI=OFF) refuses to start under an MPI launcher that asks for
// more than one process, rather than running the whole study once per process.
//
// Without MPI, a job array shares a study by shards (`--shard K/N`): shard K runs the tasks
// whose place in the study's task list is K modulo N, into its own results file, and writes no
// report; `vorodg merge DIR` gathers the shards' results and writes the reports (report-only:
// a run without a result is an error, not run).
#include <filesystem>
#include <string>

namespace vorodg {

struct Shard {
  int index = 0, count = 1;  // this process runs the tasks whose place is index modulo count
};

class Ensemble {
 public:
  /// Joins the MPI job when there is one (before anything else in main). Throws InputError if
  /// this build lacks MPI and the launcher asked for more than one process.
  static void start(int& argc, char**& argv);
  /// Leaves the MPI job (at the end of main; a no-op without one).
  static void stop();
  /// Ends every process of the job with `code` (an error on one rank must not leave the
  /// others waiting for it); returns without MPI.
  static void abort(int code);

  static int rank();
  static int size();
  static bool coordinator() { return rank() == 0; }
  static bool built_with_mpi();

  /// Throws InputError unless 0 <= index < count, or if this is an MPI job of several ranks.
  static void set_shard(Shard shard);
  static const Shard& shard();
  static void set_report_only(bool on);
  static bool report_only();
  /// Whether this process writes the reports: the coordinator of a whole study.
  static bool writes_reports() { return coordinator() && shard().count == 1; }
  /// Where this process appends its results, for the study results file `jsonl`: the file
  /// itself, or a shard's own beside it (results.shard-K-of-N.jsonl).
  static std::filesystem::path own_results(const std::filesystem::path& jsonl);
  /// Whether `name` is a shard's results file.
  static bool is_shard_results(const std::string& name);
};

}  // namespace vorodg
