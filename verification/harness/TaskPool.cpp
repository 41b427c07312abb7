#include "verification/harness/TaskPool.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <numeric>
#include <thread>

#include "core/util/Errors.hpp"
#include "core/util/StopRequest.hpp"
#include "verification/harness/Ensemble.hpp"
#include "verification/harness/TaskPoolMpi.hpp"

namespace vorodg {

std::vector<std::size_t> task_order(const std::vector<Task>& tasks) {
  std::vector<std::size_t> order(tasks.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return tasks[a].cost > tasks[b].cost; });
  return order;
}

void run_tasks(const std::vector<Task>& all, int threads,
               const std::function<TaskOutput(const Task&)>& execute,
               const std::function<void(const Task&, const TaskOutput&)>& record) {
  const Shard& shard = Ensemble::shard();
  std::vector<Task> tasks;
  for (const Task& task : all)
    if (task.place % shard.count == shard.index) tasks.push_back(task);
  if (Ensemble::report_only() && !tasks.empty()) {
    std::size_t runs = 0;
    for (const Task& task : tasks) runs += task.runs.size();
    throw InputError(std::to_string(runs) + " runs have no results yet: a shard has not " +
                     "finished (run it again, then merge)");
  }
  if (Ensemble::size() > 1) {
    run_tasks_mpi(tasks, threads, execute, record);
    return;
  }
  const std::vector<std::size_t> order = task_order(tasks);
  std::atomic<std::size_t> next{0};
  std::mutex lock;
  // The first exception out of a task (a run stopped on request, bad input met late) ends the
  // pool: the other workers finish (or checkpoint) what they hold and take nothing new; it is
  // rethrown once all have joined.
  std::exception_ptr failure;
  auto worker = [&] {
    for (std::size_t k; !stop_requested() && (k = next++) < order.size();) {
      const Task& task = tasks[order[k]];
      try {
        const TaskOutput output = execute(task);
        std::lock_guard<std::mutex> guard(lock);
        record(task, output);
      } catch (...) {
        std::lock_guard<std::mutex> guard(lock);
        if (!failure) failure = std::current_exception();
        next = order.size();
      }
    }
  };
  const int workers = std::clamp(static_cast<int>(tasks.size()), 1, std::max(threads, 1));
  std::vector<std::thread> pool;
  for (int t = 0; t < workers; ++t) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  if (stop_requested() && next < order.size())
    throw Interrupted("stopped by signal " + std::to_string(stop_signal()) + " before " +
                      std::to_string(order.size() - std::min(next.load(), order.size())) +
                      " tasks started");
}

}  // namespace vorodg
