#include "verification/study/StudyRunner.hpp"

#include <fstream>
#include <map>
#include <set>

#include "core/mesh/MeshValidator.hpp"
#include "core/util/BlasInfo.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "core/util/Random.hpp"
#include "verification/harness/Ensemble.hpp"
#include "verification/harness/ResumableRuns.hpp"
#include "verification/harness/TaskPool.hpp"
#include "verification/study/StudyProgress.hpp"

namespace vorodg {
namespace {

using nlohmann::json;

/// Lines already in results.jsonl, by run id; a line cut short by a killed run is ignored (its
/// run is simply done again).
StudyRun make_run(const Scene& scene, int m, int level, int realization, const std::string& problem,
                  double nu, int f, std::optional<double> kp) {
  const SceneMesh& mesh = scene.meshes[m];
  const SceneFormulation& form = scene.formulations[f];
  StudyRun run;
  run.mesh = m;
  run.level = level;
  run.realization = realization;
  run.mesh_label = mesh.label;
  run.family = mesh.family;
  run.size = mesh.sizes[level];
  // A pure function of the scene seed, the level and the realization.
  run.seed = derive_seed(derive_seed(mesh.seed, level), realization);
  run.problem = problem;
  run.nu = nu;
  run.formulation = f;
  run.formulation_name = form.settings.formulation;
  run.formulation_label = form.label;
  run.kp = kp;
  run.variant = kp ? form.label + " kp=" + fmt(*kp) : form.label;
  run.id = mesh.label + "/L" + std::to_string(level) + "/R" + std::to_string(realization) + "/" +
           problem + "/nu=" + fmt(nu, 12) + "/" + run.variant;
  return run;
}

/// The mesh a run's (mesh, level, realization) stands for, or the reason it could not be made.
std::optional<GeneratedMesh> make_mesh(const Scene& scene, const StudyRun& run,
                                       std::string& error) {
  const MeshSpec spec = scene.meshes[run.mesh].spec(scene.domain, run.level, run.seed);
  try {
    GeneratedMesh mesh = generate_mesh(spec);
    const auto report = validate_mesh(mesh.mesh);
    if (report.ok()) return mesh;
    error = "invalid mesh: " + report.defects.front().what;
  } catch (const std::exception& e) {
    error = e.what();
  }
  return std::nullopt;
}

RunRecord solve_run(const Scene& scene, const StudyRun& run, const GeneratedMesh* mesh,
                    SharedMeshWork* shared, const std::string& mesh_error) {
  RunRecord record{run, std::nullopt, ""};
  try {  // a run that breaks down is a reported outcome
    if (!mesh) throw InputError(mesh_error);
    const SolveResult r = run_solve(mesh->mesh, run_settings(scene, run), shared);
    record.metrics = run_metrics(mesh->mesh, r);
  } catch (const std::exception& e) {
    record.error = e.what();
  }
  return record;
}

}  // namespace

std::vector<StudyRun> expand_runs(const Scene& scene) {
  std::vector<StudyRun> runs;
  for (int m = 0; m < static_cast<int>(scene.meshes.size()); ++m)
    for (int level = 0; level < static_cast<int>(scene.meshes[m].sizes.size()); ++level)
      for (int r = 0; r < scene.meshes[m].realizations; ++r)
        for (const std::string& problem : scene.problems)
          for (double nu : scene.nu)
            for (int f = 0; f < static_cast<int>(scene.formulations.size()); ++f) {
              const SceneFormulation& form = scene.formulations[f];
              if (!form.is_dg()) runs.push_back(make_run(scene, m, level, r, problem, nu, f, {}));
              for (double kp : form.kp)
                runs.push_back(make_run(scene, m, level, r, problem, nu, f, kp));
            }
  std::set<std::string> ids;
  for (const StudyRun& run : runs)
    if (!ids.insert(run.id).second)
      throw InputError("scene " + scene.path.string() + ": two runs are both '" + run.id +
                       "' (give the formulations or meshes distinct labels)");
  return runs;
}

SolveSettings run_settings(const Scene& scene, const StudyRun& run) {
  // The formulation's settings hold the scene's material and outputs already (Scene.hpp).
  SolveSettings settings = scene.formulations[run.formulation].settings;
  settings.problem = run.problem;
  settings.nu = run.nu;
  settings.element.threads = 1;  // one run per core
  if (run.kp) settings.dg.kp = *run.kp;
  return settings;
}

namespace {

/// The output folder, made; throws InputError if it cannot be.
void make_output_folder(const std::filesystem::path& out) {
  std::error_code ec;
  std::filesystem::create_directories(out, ec);
  if (!std::filesystem::is_directory(out))
    throw InputError("output folder '" + out.string() + "' cannot be created" +
                     (ec ? " (" + ec.message() + ")" : std::string()));
}

/// Each run's record where results.jsonl (or this shard's own file) holds one of this version.
std::vector<std::optional<RunRecord>> finished_records(const std::vector<StudyRun>& runs,
                                                       const std::filesystem::path& results_file,
                                                       const std::filesystem::path& own_file) {
  std::map<std::string, json> lines = read_finished_runs(results_file);
  if (own_file != results_file) lines.merge(read_finished_runs(own_file));
  std::vector<std::optional<RunRecord>> records(runs.size());
  for (std::size_t i = 0; i < runs.size(); ++i)
    if (const auto line = lines.find(runs[i].id); line != lines.end()) try {
        records[i] = record_from_json(runs[i], line->second);
      } catch (const std::exception&) {  // not a record of this version: run it again
      }
  return records;
}

/// One task per mesh (mesh, level, realization) with runs still to do, each with its place
/// among every mesh of the study, finished or not (what shards split by).
std::vector<Task> mesh_tasks(const std::vector<StudyRun>& runs,
                             const std::vector<std::optional<RunRecord>>& records,
                             const std::vector<double>& costs) {
  std::map<std::tuple<int, int, int>, std::vector<std::size_t>> pending;
  std::map<std::tuple<int, int, int>, int> place;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::tuple key{runs[i].mesh, runs[i].level, runs[i].realization};
    place.emplace(key, 0);
    if (!records[i]) pending[key].push_back(i);
  }
  int next_place = 0;
  for (auto& [key, p] : place) p = next_place++;
  std::vector<Task> tasks;
  for (const auto& [key, list] : pending) {
    Task task{{}, 0.0, place.at(key)};
    for (std::size_t i : list) task.runs.push_back(static_cast<int>(i)), task.cost += costs[i];
    tasks.push_back(std::move(task));
  }
  return tasks;
}

/// A task's runs: the mesh made once, and every run on it sharing its element tables and
/// symbolic analyses; each run's record as a JSON line.
TaskOutput solve_task(const Scene& scene, const std::vector<StudyRun>& runs, const Task& task) {
  TaskOutput output;
  std::string mesh_error;
  const auto mesh = make_mesh(scene, runs[task.runs.front()], mesh_error);
  std::optional<SharedMeshWork> shared;
  if (mesh) shared.emplace(mesh->mesh);
  for (int i : task.runs)
    output.lines.push_back(to_json(solve_run(scene, runs[i], mesh ? &*mesh : nullptr,
                                             shared ? &*shared : nullptr, mesh_error))
                               .dump());
  return output;
}

}  // namespace

std::vector<RunRecord> run_study(const Scene& scene, const StudyOptions& options) {
  const std::vector<StudyRun> runs = expand_runs(scene);  // refuses a bad scene before any output
  make_output_folder(options.out);
  const std::filesystem::path results_file = options.out / "results.jsonl";
  const std::filesystem::path own_file = Ensemble::own_results(results_file);
  std::vector<std::optional<RunRecord>> records = finished_records(runs, results_file, own_file);
  std::vector<double> costs;
  std::vector<bool> done;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    costs.push_back(expected_cost(scene, runs[i]));
    done.push_back(records[i].has_value());
  }
  const std::vector<Task> tasks = mesh_tasks(runs, records, costs);
  std::ofstream out(own_file, std::ios::app);
  if (!out) throw InputError("cannot write '" + own_file.string() + "'");
  StudyProgress progress(costs, done, options.progress && Ensemble::coordinator());
  // One run per core: the BLAS must not start threads of its own on top. Always one, so that
  // the results (the BLAS's summation order included) do not depend on --threads.
  {
    const ScopedBlasThreads blas(1);
    run_tasks(
        tasks, options.threads, [&](const Task& task) { return solve_task(scene, runs, task); },
        [&](const Task& task, const TaskOutput& output) {
          for (std::size_t k = 0; k < task.runs.size(); ++k) {
            const int i = task.runs[k];
            // At once: a kill loses only the tasks in flight (a task is the unit a rank reports).
            out << output.lines[k] << "\n" << std::flush;
            // Through the line, as a resumed study reads it: the same records either way.
            records[i] = record_from_json(runs[i], json::parse(output.lines[k]));
            progress.finished(i);
          }
        });
  }
  if (!Ensemble::writes_reports()) return {};  // the coordinator of a whole study has them all

  std::vector<RunRecord> results;
  for (auto& record : records) results.push_back(std::move(*record));
  return results;
}

}  // namespace vorodg
