#include "verification/study/ResumableRuns.hpp"

#include <omp.h>
#include <algorithm>
#include <atomic>
#include <fstream>
#include <iostream>
#include <mutex>
#include <thread>

#include "core/util/BlasInfo.hpp"

namespace vorodg {

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
    const std::vector<std::string>& ids, const std::filesystem::path& jsonl, int threads,
    bool progress, const std::function<RunOutcome(std::size_t)>& execute) {
  std::map<std::string, nlohmann::json> done = read_finished_runs(jsonl);
  std::mutex lock;
  std::ofstream append(jsonl, std::ios::app);
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    omp_set_num_threads(1);  // each run on its own thread: no nested OpenMP teams to spin
    omp_set_dynamic(1);      // CHOLMOD asks for 4 threads whatever the setting: let them shrink
    for (std::size_t i; (i = next++) < ids.size();) {
      {
        std::lock_guard<std::mutex> guard(lock);
        if (done.count(ids[i])) continue;
      }
      const RunOutcome outcome = execute(i);
      std::lock_guard<std::mutex> guard(lock);
      append << outcome.record.dump() << '\n' << std::flush;
      done[ids[i]] = outcome.record;
      if (progress) std::cout << "  " << outcome.progress << "\n" << std::flush;
    }
  };
  // One run per thread, and OpenBLAS's threads only where threads outnumber the runs left (a
  // single fine run gets them all; otherwise they would only spin against the workers).
  const auto left =
      std::count_if(ids.begin(), ids.end(), [&](const std::string& id) { return !done.count(id); });
  const int workers = std::clamp(static_cast<int>(left), 1, std::max(threads, 1));
  const int blas_threads = set_blas_threads(std::max(1, threads / workers));
  std::vector<std::thread> pool;
  for (int t = 0; t < workers; ++t) pool.emplace_back(worker);
  for (std::thread& t : pool) t.join();
  set_blas_threads(blas_threads);
  return done;
}

}  // namespace vorodg
