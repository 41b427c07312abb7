#include "verification/harness/TaskPoolMpi.hpp"

#include <chrono>
#include <condition_variable>
#include <deque>
#include <iostream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>
#include <utility>

#include "core/util/Errors.hpp"
#include "verification/harness/Ensemble.hpp"

#ifdef VORODG_HAVE_MPI
#include <mpi.h>
#endif

namespace vorodg {

#ifndef VORODG_HAVE_MPI

void run_tasks_mpi(const std::vector<Task>&, int, const std::function<TaskOutput(const Task&)>&,
                   const std::function<void(const Task&, const TaskOutput&)>&) {
  throw InputError("task pool: this vorodg was built without MPI");
}

#else

namespace {

// A worker rank asks with kRequest (empty) whenever one of its threads is free; the
// coordinator answers kTask: the task's index and run indices, or nothing when none is left.
// A finished task comes back as kResult: its index and output, as JSON.
//
// A study runs its pools one after another (variants, sweeps), and a rank told that one pool is
// done goes on to ask for the next while the coordinator still finishes the last. So the tags
// carry the pool's number: every rank counts the pools it joins, in the same order, and the
// coordinator only ever listens to the current pool's tags.
enum Kind { kRequest = 1, kTask = 2, kResult = 3 };
int g_pool = 0;
int tag(Kind kind) {
  return 3 * (g_pool % 10000) + kind;  // MPI guarantees tags up to 32767
}

std::string pack(std::size_t index, const TaskOutput& out) {
  return nlohmann::json{{"task", index}, {"lines", out.lines}, {"notes", out.notes}}.dump();
}

/// Tasks for a process's own worker threads, and their outputs, behind one lock.
class LocalQueue {
 public:
  void push_task(std::size_t index, Task task) {
    std::lock_guard<std::mutex> guard(lock_);
    tasks_.emplace_back(index, std::move(task));
    ready_.notify_all();
  }
  void close() {
    std::lock_guard<std::mutex> guard(lock_);
    closed_ = true;
    ready_.notify_all();
  }
  /// The next task, waiting for one; nothing once closed and empty.
  std::optional<std::pair<std::size_t, Task> > take() {
    std::unique_lock<std::mutex> guard(lock_);
    ready_.wait(guard, [&] { return closed_ || !tasks_.empty(); });
    if (tasks_.empty()) return std::nullopt;
    auto task = std::move(tasks_.front());
    tasks_.pop_front();
    return task;
  }
  void push_output(std::size_t index, TaskOutput out) {
    std::lock_guard<std::mutex> guard(lock_);
    outputs_.emplace_back(index, std::move(out));
    done_.notify_all();
  }
  /// Every output so far; with `wait`, waits for at least one.
  std::deque<std::pair<std::size_t, TaskOutput> > outputs(bool wait) {
    std::unique_lock<std::mutex> guard(lock_);
    if (wait) done_.wait(guard, [&] { return !outputs_.empty(); });
    return std::exchange(outputs_, {});
  }

 private:
  std::mutex lock_;
  std::condition_variable ready_, done_;
  std::deque<std::pair<std::size_t, Task> > tasks_;
  std::deque<std::pair<std::size_t, TaskOutput> > outputs_;
  bool closed_ = false;
};

std::vector<std::thread> start_workers(int threads, LocalQueue& queue,
                                       const std::function<TaskOutput(const Task&)>& execute) {
  std::vector<std::thread> pool;
  for (int t = 0; t < std::max(threads, 1); ++t)
    pool.emplace_back([&] {
      try {
        while (auto task = queue.take()) queue.push_output(task->first, execute(task->second));
      } catch (const Interrupted& e) {
        // Its checkpoint is written; the ranks cannot finish the protocol, so the job ends
        // here, with the code that says "resumable".
        std::cerr << "vorodg: stopped: " << e.what() << "\n";
        MPI_Abort(MPI_COMM_WORLD, kExitInterrupted);
      }
    });
  return pool;
}

void coordinate(const std::vector<Task>& tasks, int threads,
                const std::function<TaskOutput(const Task&)>& execute,
                const std::function<void(const Task&, const TaskOutput&)>& record) {
  const std::vector<std::size_t> order = task_order(tasks);
  std::size_t next = 0, finished = 0;
  int ranks_done = 0;
  LocalQueue local;
  // The coordinator's own workers get a task whenever one is free, like any other rank's.
  int local_idle = std::max(threads, 1);
  std::vector<std::thread> pool = start_workers(threads, local, execute);
  while (finished < tasks.size() || ranks_done < Ensemble::size() - 1) {
    bool busy = false;
    for (; local_idle > 0 && next < order.size(); --local_idle, busy = true)
      local.push_task(order[next], tasks[order[next]]), ++next;
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, tag(kRequest), MPI_COMM_WORLD, &flag, &status);
    if (!flag) MPI_Iprobe(MPI_ANY_SOURCE, tag(kResult), MPI_COMM_WORLD, &flag, &status);
    if (flag && status.MPI_TAG == tag(kRequest)) {
      MPI_Recv(nullptr, 0, MPI_INT, status.MPI_SOURCE, tag(kRequest), MPI_COMM_WORLD,
               MPI_STATUS_IGNORE);
      std::vector<int> message;
      if (next < order.size()) {
        message.push_back(static_cast<int>(order[next]));
        const auto& runs = tasks[order[next++]].runs;
        message.insert(message.end(), runs.begin(), runs.end());
      } else {
        ++ranks_done;
      }
      MPI_Send(message.data(), static_cast<int>(message.size()), MPI_INT, status.MPI_SOURCE,
               tag(kTask), MPI_COMM_WORLD);
      busy = true;
    } else if (flag) {  // a result
      int size = 0;
      MPI_Get_count(&status, MPI_CHAR, &size);
      std::string text(size, '\0');
      MPI_Recv(text.data(), size, MPI_CHAR, status.MPI_SOURCE, tag(kResult), MPI_COMM_WORLD,
               MPI_STATUS_IGNORE);
      const nlohmann::json j = nlohmann::json::parse(text);
      const std::size_t index = j.at("task");
      record(tasks[index], {j.at("lines"), j.at("notes")});
      ++finished, busy = true;
    }
    for (auto& [index, out] : local.outputs(false)) {
      record(tasks[index], out);
      ++finished, ++local_idle, busy = true;
    }
    if (!busy) std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  local.close();
  for (std::thread& t : pool) t.join();
}

void work(int threads, const std::function<TaskOutput(const Task&)>& execute) {
  LocalQueue local;
  std::vector<std::thread> pool = start_workers(threads, local, execute);
  int idle = std::max(threads, 1), in_flight = 0;
  bool done = false;
  while (!done || in_flight > 0) {
    while (!done && idle > 0) {
      MPI_Send(nullptr, 0, MPI_INT, 0, tag(kRequest), MPI_COMM_WORLD);
      MPI_Status status;
      MPI_Probe(0, tag(kTask), MPI_COMM_WORLD, &status);
      int size = 0;
      MPI_Get_count(&status, MPI_INT, &size);
      std::vector<int> message(size);
      MPI_Recv(message.data(), size, MPI_INT, 0, tag(kTask), MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (message.empty()) {
        done = true;
        break;
      }
      local.push_task(message[0], Task{{message.begin() + 1, message.end()}});
      --idle, ++in_flight;
    }
    if (in_flight == 0) continue;
    for (auto& [index, out] : local.outputs(true)) {
      const std::string text = pack(index, out);
      MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, tag(kResult),
               MPI_COMM_WORLD);
      ++idle, --in_flight;
    }
  }
  local.close();
  for (std::thread& t : pool) t.join();
}

}  // namespace

void run_tasks_mpi(const std::vector<Task>& tasks, int threads,
                   const std::function<TaskOutput(const Task&)>& execute,
                   const std::function<void(const Task&, const TaskOutput&)>& record) {
  ++g_pool;
  if (Ensemble::coordinator())
    coordinate(tasks, threads, execute, record);
  else
    work(threads, execute);
}

#endif

}  // namespace vorodg
