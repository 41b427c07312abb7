#include "verification/study/StudyRunner.hpp"

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include "core/mesh/MeshValidator.hpp"
#include "core/util/BlasInfo.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "core/util/PeakMemory.hpp"
#include "core/util/Random.hpp"
#include "core/util/Stopwatch.hpp"

namespace vorodg {
namespace {

using nlohmann::json;

std::string variant_name(const SceneFormulation& f, double kp) {
  return f.kp.empty() ? f.label : f.label + " kp=" + fmt(kp);
}

/// Results already in results.jsonl; a line cut short by a killed run is ignored (its run is
/// simply done again).
std::map<std::string, json> read_results(const std::filesystem::path& file) {
  std::map<std::string, json> done;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    try {
      json r = json::parse(line);
      if (r.contains("id")) done[r["id"].get<std::string>()] = r;
    } catch (const json::exception&) {
    }
  }
  return done;
}

class Progress {
 public:
  Progress(std::size_t total, std::size_t already, bool show)
      : total_(total), done_(already), show_(show), tty_(isatty(fileno(stderr))) {}
  void tick() {
    const std::size_t now = ++done_;
    if (!show_) return;
    const double elapsed = clock_.seconds();
    const std::size_t fresh = now - started_with_;
    const double remaining = fresh ? elapsed / fresh * (total_ - now) : 0.0;
    std::ostringstream line;
    line << "runs " << now << "/" << total_ << ", " << fmt(elapsed, 3) << " s elapsed, ~"
         << fmt(remaining, 3) << " s left";
    if (tty_) {
      const int width = 30, filled = static_cast<int>(width * now / std::max<std::size_t>(total_, 1));
      std::cerr << "\r[" << std::string(filled, '#') << std::string(width - filled, '.') << "] "
                << line.str() << "   " << std::flush;
      if (now == total_) std::cerr << "\n";
    } else if (now == total_ || now % std::max<std::size_t>(total_ / 10, 1) == 0) {
      std::cerr << line.str() << "\n";
    }
  }

 private:
  std::size_t total_;
  std::atomic<std::size_t> done_;
  std::size_t started_with_ = done_;
  bool show_, tty_;
  Stopwatch clock_;
};

json result_json(const StudyRun& run, const Scene& scene, const PolygonMesh& mesh,
                 const SolveResult& r) {
  const SceneMesh& m = scene.meshes[run.mesh];
  json j = {{"id", run.id},
            {"mesh", m.label},
            {"family", family_name(m.family)},
            {"level", run.level},
            {"size", m.sizes[run.level]},
            {"realization", run.realization},
            {"seed", run.seed},
            {"problem", run.problem},
            {"nu", run.nu},
            {"formulation", scene.formulations[run.formulation].settings.formulation},
            {"variant", run.variant},
            {"kp", run.kp},
            {"status", "ok"},
            {"cells", mesh.num_cells()},
            {"dofs", r.dofs},
            {"h_avg", mesh.h_avg()},
            {"l2_error", r.l2_error},
            {"energy_error", r.energy_error},
            {"rcond", r.rcond},
            {"factor_nonzeros", r.factor_nonzeros},
            {"iterations", r.dg ? r.dg->iterations : 1},
            {"stop_reason", r.dg ? r.dg->stop_reason : "direct"},
            {"relative_gap", r.dg ? r.dg->relative_gap : 0.0}};
  json seconds = json::object();
  for (const auto& [stage, s] : r.seconds) seconds[stage] = s;
  j["seconds"] = seconds;
  j["peak_memory_mb"] = peak_memory_mb();  // of the study process so far (runs share it)
  return j;
}

}  // namespace

std::vector<StudyRun> expand_runs(const Scene& scene) {
  std::vector<StudyRun> runs;
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    const SceneMesh& mesh = scene.meshes[m];
    for (std::size_t level = 0; level < mesh.sizes.size(); ++level)
      for (int r = 0; r < mesh.realizations; ++r)
        for (const std::string& problem : scene.problems)
          for (double nu : scene.nu)
            for (std::size_t f = 0; f < scene.formulations.size(); ++f) {
              const SceneFormulation& form = scene.formulations[f];
              const std::vector<double> kps = form.kp.empty() ? std::vector<double>{0.0} : form.kp;
              for (double kp : kps) {
                StudyRun run;
                run.mesh = static_cast<int>(m);
                run.level = static_cast<int>(level);
                run.realization = r;
                // A pure function of the scene seed, the level and the realization.
                run.seed = derive_seed(derive_seed(mesh.seed, level), r);
                run.problem = problem;
                run.nu = nu;
                run.formulation = static_cast<int>(f);
                run.kp = kp;
                run.variant = variant_name(form, kp);
                run.id = mesh.label + "/L" + std::to_string(level) + "/R" + std::to_string(r) +
                         "/" + problem + "/nu=" + fmt(nu, 12) + "/" + run.variant;
                runs.push_back(run);
              }
            }
  }
  std::set<std::string> ids;
  for (const StudyRun& run : runs)
    if (!ids.insert(run.id).second)
      throw InputError("scene " + scene.path.string() + ": two runs are both '" + run.id +
                       "' (give the formulations or meshes distinct labels)");
  return runs;
}

std::vector<json> run_study(const Scene& scene, const StudyOptions& options) {
  namespace fs = std::filesystem;
  const std::vector<StudyRun> runs = expand_runs(scene);  // refuses a bad scene before any output
  std::error_code ec;
  fs::create_directories(options.out, ec);
  if (!fs::is_directory(options.out))
    throw InputError("output folder '" + options.out.string() + "' cannot be created" +
                     (ec ? " (" + ec.message() + ")" : std::string()));
  const fs::path results_file = options.out / "results.jsonl";
  std::map<std::string, json> done = read_results(results_file);

  // Work by mesh: every pending run on the same (mesh, level, realization) shares one mesh.
  std::map<std::tuple<int, int, int>, std::vector<const StudyRun*>> pending;
  std::size_t already = 0;
  for (const StudyRun& run : runs) {
    if (done.count(run.id)) ++already;
    else pending[{run.mesh, run.level, run.realization}].push_back(&run);
  }
  std::vector<std::vector<const StudyRun*>> work;
  for (auto& [key, list] : pending) work.push_back(list);

  std::ofstream out(results_file, std::ios::app);
  if (!out) throw InputError("cannot write '" + results_file.string() + "'");
  std::mutex lock;
  Progress progress(runs.size(), already, options.progress);
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t w = next++; w < work.size(); w = next++) {
      const StudyRun& first = *work[w].front();
      const SceneMesh& m = scene.meshes[first.mesh];
      MeshSpec spec;
      spec.family = m.family;
      spec.domain = scene.domain;
      spec.size = m.sizes[first.level];
      spec.seed = first.seed;
      spec.perturbation = m.perturbation;
      spec.regularization = m.regularization;
      std::optional<GeneratedMesh> mesh;
      std::string mesh_error;
      try {
        mesh = generate_mesh(spec);
        const auto report = validate_mesh(mesh->mesh);
        if (!report.ok()) mesh_error = "invalid mesh: " + report.defects.front().what;
      } catch (const std::exception& e) {
        mesh_error = e.what();
      }
      for (const StudyRun* run : work[w]) {
        json j;
        try {
          if (!mesh_error.empty()) throw InputError(mesh_error);
          SolveSettings settings = scene.formulations[run->formulation].settings;
          settings.problem = run->problem;
          settings.E = scene.E;
          settings.nu = run->nu;
          settings.plane = scene.plane;
          settings.load = scene.load;
          settings.energy_error = scene.energy_error;
          settings.element.threads = 1;
          if (run->kp > 0) settings.dg.kp = run->kp;
          const SolveResult r = run_solve(mesh->mesh, settings);
          j = result_json(*run, scene, mesh->mesh, r);
        } catch (const std::exception& e) {  // a run that breaks down is a reported outcome
          j = {{"id", run->id}, {"mesh", scene.meshes[run->mesh].label}, {"level", run->level},
               {"size", scene.meshes[run->mesh].sizes[run->level]}, {"realization", run->realization},
               {"seed", run->seed}, {"problem", run->problem}, {"nu", run->nu},
               {"formulation", scene.formulations[run->formulation].settings.formulation},
               {"variant", run->variant}, {"kp", run->kp}, {"status", "failed"}, {"error", e.what()}};
        }
        {
          std::lock_guard<std::mutex> guard(lock);
          out << j.dump() << "\n" << std::flush;  // appended at once: a kill loses nothing done
          done[run->id] = j;
        }
        progress.tick();
      }
    }
  };
  // One run per core: the BLAS must not start threads of its own on top. Always one, so that
  // the results (the BLAS's summation order included) do not depend on --threads.
  const int blas_threads = set_blas_threads(1);
  std::vector<std::thread> threads;
  for (int t = 0; t < std::max(options.threads, 1); ++t) threads.emplace_back(worker);
  for (auto& t : threads) t.join();
  set_blas_threads(blas_threads);

  std::vector<json> results;
  for (const StudyRun& run : runs) results.push_back(done.at(run.id));
  return results;
}

}  // namespace vorodg
