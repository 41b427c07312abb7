#include "verification/harness/ResumableRuns.hpp"

#include <algorithm>
#include <fstream>
#include <iostream>

#include "core/util/BlasInfo.hpp"
#include "verification/harness/Ensemble.hpp"
#include "verification/harness/TaskPool.hpp"

namespace vorodg {

double level_cost(const SceneMesh& mesh, int level) {
  const double size = mesh.sizes.at(level);
  return 1.0 / (size * size * size);
}

std::map<std::string, nlohmann::json> read_finished_runs(const std::filesystem::path& jsonl) {
  std::map<std::string, nlohmann::json> done;
  std::ifstream in(jsonl);
  for (std::string line; std::getline(in, line);) {
    try {
      const nlohmann::json j = nlohmann::json::parse(line);
      done[j.at("id")] = j;
    } catch (const nlohmann::json::exception&) {  // a line cut short by a stop: it runs again
    }
  }
  return done;
}

std::map<std::string, nlohmann::json> run_resumable(
    const std::vector<std::string>& ids, const std::vector<double>& costs,
    const std::filesystem::path& jsonl, int threads, bool progress,
    const std::function<RunOutcome(std::size_t)>& execute) {
  const std::filesystem::path own = Ensemble::own_results(jsonl);
  std::map<std::string, nlohmann::json> done = read_finished_runs(jsonl);
  if (own != jsonl) done.merge(read_finished_runs(own));
  std::vector<Task> tasks;  // one per run left
  for (std::size_t i = 0; i < ids.size(); ++i)
    if (!done.count(ids[i]))
      tasks.push_back({{static_cast<int>(i)}, costs.at(i), static_cast<int>(i)});
  std::ofstream append(own, std::ios::app);
  // One run per thread, and OpenBLAS's threads only where threads outnumber the runs left (a
  // single fine run gets them all; otherwise they would only spin against the workers).
  const int workers = std::clamp(static_cast<int>(tasks.size()), 1, std::max(threads, 1));
  const ScopedBlasThreads blas(std::max(1, threads / workers));
  run_tasks(
      tasks, threads,
      [&](const Task& task) {
        const RunOutcome outcome = execute(task.runs.front());
        return TaskOutput{{outcome.record.dump()}, {outcome.progress}};
      },
      [&](const Task& task, const TaskOutput& output) {
        append << output.lines.front() << '\n' << std::flush;
        done[ids[task.runs.front()]] = nlohmann::json::parse(output.lines.front());
        if (progress) std::cout << "  " << output.notes.front() << "\n" << std::flush;
      });
  return done;
}

}  // namespace vorodg
