#include "verification/api/SceneRuns.hpp"

#include "core/util/Errors.hpp"
#include "verification/harness/SceneVariants.hpp"
#include "verification/kinds/dynamics/DynamicsRun.hpp"
#include "verification/kinds/fracture/FractureRun.hpp"

namespace vorodg {
namespace {

/// The scene's part (itself, or the variant of that label).
template <class SceneT>
const SceneT& part(const SceneT& scene, const std::optional<std::string>& variant) {
  const std::vector<const SceneT*> parts = study_parts(scene);
  std::string labels;
  for (const SceneT* p : parts) {
    if (variant ? p->label == *variant : parts.size() == 1) return *p;
    labels += (labels.empty() ? "" : ", ") + p->label;
  }
  throw InputError(variant ? "variant '" + *variant + "': no such variant (" + labels + ")"
                           : "the scene has variants: give variant= one of " + labels);
}

/// The run of the part's meshes: by place (0, 1, ...) or by id ("rcp-L0-R2").
EnsembleRunId pick_run(const std::vector<SceneMesh>& meshes,
                       const std::variant<int, std::string>& run) {
  const std::vector<EnsembleRunId> runs = ensemble_runs(meshes);
  if (const int* i = std::get_if<int>(&run)) {
    if (*i < 0 || *i >= static_cast<int>(runs.size()))
      throw InputError("run " + std::to_string(*i) + ": expected 0 <= run < " +
                       std::to_string(runs.size()));
    return runs[*i];
  }
  std::string ids;
  for (const EnsembleRunId& id : runs) {
    if (id.id() == std::get<std::string>(run)) return id;
    ids += (ids.empty() ? "" : ", ") + id.id();
  }
  throw InputError("run '" + std::get<std::string>(run) + "': no such run (" + ids + ")");
}

}  // namespace

SceneRunResult fracture_scene_run(const SceneRunChoice& choice,
                                  const FracturePathObserver& observe) {
  const FractureScene parsed = parse_fracture_scene(choice.text, choice.source);
  const FractureScene& s = part(parsed, choice.variant);
  const EnsembleRunId id = pick_run(s.meshes, choice.run);
  const FractureRecord r = run_fracture(s, id, choice.output, observe);
  return {fracture_record_json(r), fracture_run_mesh(s, id).mesh};
}

SceneRunResult fragmentation_scene_run(
    const SceneRunChoice& choice, bool force,
    const std::function<void(const ExplicitSimulation&)>& at_end) {
  const DynamicsScene parsed = parse_dynamics_scene(choice.text, choice.source, force);
  const DynamicsScene& s = part(parsed, choice.variant);
  if (!s.fragmentation)
    throw InputError(choice.source +
                     ": a dynamics scene; fragmentation_run takes a fragmentation one");
  const EnsembleRunId id = pick_run(s.meshes, choice.run);
  std::optional<PolygonMesh> mesh;
  const DynamicsRecord r = run_dynamics(s, id, choice.output, [&](const ExplicitSimulation& sim) {
    mesh.emplace(sim.mesh());
    if (at_end) at_end(sim);
  });
  if (!mesh) throw NumericalError(choice.source + ": the run ended before its simulation existed");
  return {dynamics_record_json(s, r), std::move(*mesh)};
}

}  // namespace vorodg
