#pragma once
// The task pool of every study. A task is the runs that share one mesh (the convergence family)
// or one run (the ensemble studies, which build their mesh per run). Tasks start largest
// expected cost first, ties in list order, so that the longest ones do not end up running alone
// at the end of a study.
//
// One process: `threads` worker threads take the tasks in turn.
//
// An MPI job (Ensemble): every rank runs `threads` worker threads. The coordinator's main
// thread hands the tasks out one at a time, to its own workers and to the other ranks' as they
// come free, and receives each task's output. Only each process's main thread calls MPI, so
// MPI_THREAD_FUNNELED is enough. The other ranks do not need the task list: a task travels as
// its run indices, which every rank resolves in the study's own run list.
//
// The output of every task reaches `record` on the coordinator alone, one call at a time, in
// the order tasks finish. A study's reports must therefore not depend on that order, and they
// do not: they list runs in the study's own order.
#include <functional>
#include <string>
#include <vector>

namespace vorodg {

struct Task {
  std::vector<int> runs;  // indices into the study's run list
  double cost = 1.0;      // expected, in any unit: only the order matters
  int place = 0;          // among all the study's tasks, finished or not: what shards split by
};

struct TaskOutput {
  std::vector<std::string> lines;  // one results.jsonl line per run
  std::vector<std::string> notes;  // console lines
};

/// Runs every task once (see above): under `--shard K/N` only those whose place is K modulo N.
/// On the ranks other than the coordinator `tasks` is not read and `record` is never called.
/// An exception out of `execute` ends the process (callers turn a run's failure into a failed
/// record). In report-only mode (`vorodg merge`) any task left is an InputError.
void run_tasks(const std::vector<Task>& tasks, int threads,
               const std::function<TaskOutput(const Task&)>& execute,
               const std::function<void(const Task&, const TaskOutput&)>& record);

/// The tasks' start order: largest cost first, ties in list order.
std::vector<std::size_t> task_order(const std::vector<Task>& tasks);

}  // namespace vorodg
