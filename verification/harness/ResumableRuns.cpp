#include "verification/harness/ResumableRuns.hpp"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <set>

#include "core/util/BlasInfo.hpp"
#include "core/util/Errors.hpp"
#include "verification/harness/Ensemble.hpp"
#include "verification/harness/RunProgress.hpp"
#include "verification/harness/TaskPool.hpp"

namespace vorodg {
namespace {

using nlohmann::json;

/// The output folder, made; throws InputError if it cannot be.
void make_folder(const std::filesystem::path& folder) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (!std::filesystem::is_directory(folder))
    throw InputError("output folder '" + folder.string() + "' cannot be created" +
                     (ec ? " (" + ec.message() + ")" : std::string()));
}

/// The finished lines of results.jsonl and of this shard's own file that the kind reads.
std::map<std::string, json> finished_lines(const RunPlan& plan, const std::filesystem::path& jsonl,
                                           const ReadableLine& readable) {
  std::map<std::string, json> lines = read_finished_runs(jsonl);
  const std::filesystem::path own = Ensemble::own_results(jsonl);
  if (own != jsonl) lines.merge(read_finished_runs(own));
  if (!readable) return lines;
  for (std::size_t i = 0; i < plan.ids.size(); ++i)
    if (const auto line = lines.find(plan.ids[i]);
        line != lines.end() && !readable(i, line->second))
      lines.erase(line);  // not a record of this version: it runs again
  return lines;
}

/// Says on stderr how many finished lines belong to no run of the plan (written by another
/// version, or before the scene was edited): they are kept in the file and ignored.
void note_orphans(const RunPlan& plan, const std::map<std::string, json>& lines,
                  const std::filesystem::path& jsonl) {
  if (!Ensemble::coordinator()) return;
  const std::set<std::string> ids(plan.ids.begin(), plan.ids.end());
  std::size_t orphans = 0;
  for (const auto& [id, line] : lines) orphans += ids.count(id) == 0;
  if (orphans > 0)
    std::cerr << "vorodg: note: " << jsonl.string() << " holds " << orphans
              << " finished run(s) this scene does not have (another version, or an edited "
                 "scene); they are ignored\n";
}

/// Opens a results file for appending records. A stop may have cut the last line short (or
/// left a whole record without its newline): that line is ended first, so the next record
/// starts a line of its own and every later reader still parses it.
std::ofstream open_for_records(const std::filesystem::path& file) {
  bool ends_cut = false;
  if (std::ifstream in(file, std::ios::binary | std::ios::ate); in && in.tellg() > 0) {
    in.seekg(-1, std::ios::end);
    ends_cut = in.get() != '\n';
  }
  std::ofstream append(file, std::ios::app | std::ios::binary);
  if (!append) throw InputError("cannot write '" + file.string() + "'");
  if (ends_cut) append << '\n' << std::flush;
  return append;
}

/// One task per block with runs still to do, holding those runs, at the block's place.
std::vector<Task> pending_tasks(const RunPlan& plan, const std::vector<bool>& done) {
  std::vector<Task> tasks;
  for (std::size_t b = 0; b < plan.blocks.size(); ++b) {
    Task task{{}, 0.0, static_cast<int>(b)};
    for (std::size_t i : plan.blocks[b])
      if (!done[i]) task.runs.push_back(static_cast<int>(i)), task.cost += plan.costs.at(i);
    if (!task.runs.empty()) tasks.push_back(std::move(task));
  }
  return tasks;
}

}  // namespace

RunPlan RunPlan::one_per_run(std::vector<std::string> ids, std::vector<double> costs) {
  RunPlan plan{std::move(ids), std::move(costs), {}};
  for (std::size_t i = 0; i < plan.ids.size(); ++i) plan.blocks.push_back({i});
  return plan;
}

double level_cost(const SceneMesh& mesh, int level) {
  const double size = mesh.sizes.at(level);
  return 1.0 / (size * size * size);
}

std::map<std::string, json> read_finished_runs(const std::filesystem::path& jsonl) {
  std::map<std::string, json> done;
  std::ifstream in(jsonl);
  for (std::string line; std::getline(in, line);) {
    try {
      const json j = json::parse(line);
      done[j.at("id")] = j;
    } catch (const json::exception&) {  // a line cut short by a stop: it runs again
    }
  }
  return done;
}

std::map<std::string, json> run_resumable(const RunPlan& plan, const std::filesystem::path& jsonl,
                                          const RunLoopOptions& options,
                                          const BlockExecutor& execute,
                                          const ReadableLine& readable) {
  make_folder(jsonl.parent_path());
  std::map<std::string, json> done = finished_lines(plan, jsonl, readable);
  note_orphans(plan, done, jsonl);
  std::vector<bool> finished;
  for (const std::string& id : plan.ids) finished.push_back(done.count(id) > 0);
  const std::vector<Task> tasks = pending_tasks(plan, finished);
  const std::filesystem::path own = Ensemble::own_results(jsonl);
  std::ofstream append = open_for_records(own);
  RunProgress progress(plan.costs, finished, options.progress && Ensemble::coordinator());
  const int workers = std::clamp(static_cast<int>(tasks.size()), 1, std::max(options.threads, 1));
  const ScopedBlasThreads blas(
      options.spare_threads_to_blas ? std::max(1, options.threads / workers) : 1);
  run_tasks(
      tasks, options.threads,
      [&](const Task& task) {
        const std::vector<std::size_t> runs(task.runs.begin(), task.runs.end());
        TaskOutput output;
        for (const RunOutcome& outcome : execute(runs)) {
          output.lines.push_back(outcome.record.dump());
          output.notes.push_back(outcome.progress);
        }
        return output;
      },
      [&](const Task& task, const TaskOutput& output) {
        for (std::size_t k = 0; k < task.runs.size(); ++k) {
          // At once: a stop loses only the tasks in flight (a task is the unit a rank reports).
          // The record and its newline in one write call, so a stop does not part them.
          append << output.lines.at(k) + '\n' << std::flush;
          done[plan.ids[task.runs[k]]] = json::parse(output.lines[k]);
          if (options.progress && !output.notes[k].empty())
            std::cout << "  " << output.notes[k] << "\n" << std::flush;
          progress.finished(task.runs[k]);
        }
      });
  return done;
}

}  // namespace vorodg
