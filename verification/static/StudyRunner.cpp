#include "verification/static/StudyRunner.hpp"

#include <cmath>
#include <numbers>
#include <set>

#include "core/mesh/MeshValidator.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "verification/harness/Ensemble.hpp"
#include "verification/harness/EnsembleRun.hpp"
#include "verification/harness/ResumableRuns.hpp"

namespace vorodg {
namespace {

using nlohmann::json;

StudyRun make_run(const Scene& scene, const EnsembleRunId& block, const std::string& problem,
                  double nu, int f, std::optional<double> kp) {
  const SceneMesh& mesh = scene.meshes[block.mesh];
  const SceneFormulation& form = scene.formulations[f];
  StudyRun run;
  run.mesh = block.mesh;
  run.level = block.level;
  run.realization = block.realization;
  run.mesh_label = mesh.label;
  run.family = mesh.family;
  run.size = mesh.sizes[block.level];
  run.seed = block.seed;  // the harness's: a pure function of the scene seed, level, realization
  run.problem = problem;
  run.nu = nu;
  run.formulation = f;
  run.formulation_name = form.settings.formulation;
  run.formulation_label = form.label;
  run.kp = kp;
  run.variant = kp ? form.label + " kp=" + fmt(*kp) : form.label;
  // The block's id, as every kind names its runs, then what this record is of the block.
  run.id = block.id() + "/" + problem + "/nu=" + fmt(nu, 12) + "/" + run.variant;
  return run;
}

/// Cells per unit area times size^2 of each family: saturated random sequential packing covers
/// about 0.547 of the area with disks of diameter d (rcp: one cell per seed; tri: about two
/// triangles per seed); a hexagon of spacing h has area (sqrt(3)/2) h^2; a square h^2.
double cells_per_size_squared(MeshFamily family) {
  switch (family) {
    case MeshFamily::rcp: return 0.547 * 4 / std::numbers::pi;
    case MeshFamily::tri: return 2 * 0.547 * 4 / std::numbers::pi;
    case MeshFamily::hex:
    case MeshFamily::perturbed_hex: return 2 / std::sqrt(3.0);
    default: return 1.0;
  }
}

/// The expected cost of a run in arbitrary units, from the scene alone (no mesh is built): its
/// expected degrees of freedom to the power 1.1 (fitted on fig26: CG time grows as DOFs^1.04,
/// DG as DOFs^1.12).
double expected_cost(const Scene& scene, const StudyRun& run) {
  const double cells =
      scene.domain.area() / (run.size * run.size) * cells_per_size_squared(run.family);
  // CG: about two vertices per cell, two DOFs each; DG: a copy of every vertex of every cell
  // (about six), which also makes its factor denser.
  const double dofs = run.kp ? 12 * cells : 4 * cells;
  return std::pow(dofs, 1.1);
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
  for (const EnsembleRunId& block : ensemble_runs(scene.meshes))
    for (const std::string& problem : scene.problems)
      for (double nu : scene.nu)
        for (int f = 0; f < static_cast<int>(scene.formulations.size()); ++f) {
          const SceneFormulation& form = scene.formulations[f];
          if (!form.is_dg()) runs.push_back(make_run(scene, block, problem, nu, f, {}));
          for (double kp : form.kp) runs.push_back(make_run(scene, block, problem, nu, f, kp));
        }
  std::set<std::string> ids;
  for (const StudyRun& run : runs)
    if (!ids.insert(run.id).second)
      throw InputError("scene " + scene.path.string() + ": two runs are both '" + run.id +
                       "' (give the formulations distinct labels)");
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

/// The harness's plan: one block per (mesh, level, realization), whose runs expand_runs lists
/// together.
RunPlan study_plan(const Scene& scene, const std::vector<StudyRun>& runs) {
  RunPlan plan;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    plan.ids.push_back(runs[i].id);
    plan.costs.push_back(expected_cost(scene, runs[i]));
    const bool same_block = i > 0 && runs[i].mesh == runs[i - 1].mesh &&
                            runs[i].level == runs[i - 1].level &&
                            runs[i].realization == runs[i - 1].realization;
    if (!same_block) plan.blocks.emplace_back();
    plan.blocks.back().push_back(i);
  }
  return plan;
}

/// A block's runs: the mesh made once, and every run on it sharing its element tables and
/// symbolic analyses.
std::vector<RunOutcome> solve_block(const Scene& scene, const std::vector<StudyRun>& runs,
                                    const std::vector<std::size_t>& block) {
  std::string mesh_error;
  const auto mesh = make_mesh(scene, runs[block.front()], mesh_error);
  std::optional<SharedMeshWork> shared;
  if (mesh) shared.emplace(mesh->mesh);
  std::vector<RunOutcome> outcomes;
  for (std::size_t i : block)
    outcomes.push_back({to_json(solve_run(scene, runs[i], mesh ? &*mesh : nullptr,
                                          shared ? &*shared : nullptr, mesh_error)),
                        ""});
  return outcomes;
}

}  // namespace

std::vector<RunRecord> run_study(const Scene& scene, const StudyOptions& options) {
  const std::vector<StudyRun> runs = expand_runs(scene);  // refuses a bad scene before any output
  // One run per core, and one BLAS thread per run: the results (the BLAS's summation order
  // included) do not depend on --threads.
  const RunLoopOptions loop{options.threads, options.progress, false};
  const auto done = run_resumable(
      study_plan(scene, runs), options.out / "results.jsonl", loop,
      [&](const std::vector<std::size_t>& block) { return solve_block(scene, runs, block); },
      [&](std::size_t i, const json& line) {
        try {
          record_from_json(runs[i], line);
          return true;
        } catch (const std::exception&) {  // not a record of this version: it runs again
          return false;
        }
      });
  if (!Ensemble::writes_reports()) return {};  // the coordinator of a whole study has them all
  std::vector<RunRecord> results;
  for (const StudyRun& run : runs) results.push_back(record_from_json(run, done.at(run.id)));
  return results;
}

}  // namespace vorodg
