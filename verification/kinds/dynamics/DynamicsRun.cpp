#include "verification/kinds/dynamics/DynamicsRun.hpp"

#include <cmath>
#include <sstream>

#include "core/element/ElasticityIntegrator.hpp"
#include "core/element/ElementTable.hpp"
#include "core/io/AtomicFile.hpp"
#include "core/io/Checkpoint.hpp"
#include "core/io/PvdCollection.hpp"
#include "core/io/StateArchive.hpp"
#include "core/io/VtuMesh.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "core/util/Stopwatch.hpp"
#include "dynamics/CellStress.hpp"
#include "dynamics/CentralDifference.hpp"
#include "dynamics/ContactForces.hpp"
#include "dynamics/ExplicitSimulation.hpp"
#include "dynamics/LumpedMass.hpp"
#include "verification/harness/RunCheckpoints.hpp"
#include "verification/kinds/dynamics/DynamicsHistory.hpp"
#include "verification/kinds/dynamics/FragmentRecord.hpp"
#include "verification/solve/SettingsSchema.hpp"

namespace fs = std::filesystem;

namespace vorodg {
namespace {

/// One frame of the series: the mesh at x = X + u with one point per node of the current DOF map
/// (so a crack shows as a gap where its nodes split), the displacement and velocity at the
/// points, each cell's mean stress (times its stiffness factor, if the material varies; taken in
/// the cell's turning frame and turned back, under corotational kinematics) and von Mises
/// stress, and any extra cell fields.
void write_frame(const fs::path& file, const PolygonMesh& mesh, const CentralDifference& run,
                 const ElasticityIntegrator& integrator,
                 const ElasticityIntegrator::MeanStrainOperators& strain,
                 const std::vector<double>& stiffness, std::vector<VtuField> cell_fields) {
  const int nodes = run.dofs().num_nodes();
  std::vector<Point> moved(nodes);
  VtuField displacement{"displacement", 2, {}}, velocity{"velocity", 2, {}};
  VtuField stress{"mean_stress", 3, {}}, von_mises{"von_mises", 1, {}};
  std::vector<int> cells;
  cells.reserve(mesh.cell_vertex_list().size());
  for (int c = 0; c < mesh.num_cells(); ++c)
    for (int k = 0; k < mesh.cell_size(c); ++k) cells.push_back(run.dofs().node(c, k));
  for (int i = 0; i < nodes; ++i) {
    const Eigen::Vector2d u = run.displacement().segment<2>(2 * i);
    moved[i] = run.node_position(i) + u;
    for (int d = 0; d < 2; ++d) {
      displacement.values.push_back(u[d]);
      velocity.values.push_back(run.velocity()[2 * i + d]);
    }
  }
  for (const Eigen::Vector3d& s : cell_mean_stresses(run, integrator, strain, stiffness)) {
    stress.values.insert(stress.values.end(), {s[0], s[1], s[2]});
    von_mises.values.push_back(integrator.material().von_mises(s));
  }
  cell_fields.insert(cell_fields.begin(), {stress, von_mises});
  // The frame's domain is the deformed bounding box (the bodies have moved off the reference one).
  Point lo = moved.front(), hi = moved.front();
  for (const Point& p : moved) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const PolygonMesh deformed(Rectangle(lo.x(), lo.y(), hi.x(), hi.y()), moved, mesh.offsets(),
                             cells);
  write_vtu(file, deformed, {{displacement, velocity}, cell_fields});
}

/// history/<name>.csv, its folder made.
fs::path history_file(const fs::path& out, const std::string& name) {
  fs::create_directories(out / "history");
  return out / "history" / (name + ".csv");
}

/// What a run writes as it goes: its history, its .pvd series (outputs.vtu) and the frames at
/// the requested snapshot times with their list.
class RunOutputs {
 public:
  RunOutputs(const ExplicitSimulation& model, const DynamicsScene& scene, const fs::path& out,
             std::string name)
      : model_(model),
        scene_(scene),
        out_(out),
        name_(std::move(name)),
        history_(history_file(out, name_)),
        series_(out / "vtu" / (name_ + ".pvd")) {
    snapshots_ << "snapshot,requested_time,time,step,file\n";
  }

  /// A row of the history.
  void record(const StepRecord& step) { history_.add(step, model_.run->contact()); }
  void flush() { history_.flush(); }

  /// A frame of the series.
  void frame() {
    const CentralDifference& run = *model_.run;
    // Absolute, so that the series lists it relative to its own folder whatever -o was.
    if (scene_.vtu)
      series_.add(run.time(), fs::absolute(write("step_" + std::to_string(run.step_count()))));
  }

  /// A frame at the first step at or after each requested time.
  void snapshots() {
    const CentralDifference& run = *model_.run;
    for (; next_ < scene_.snapshots.size() &&
           run.time() >= scene_.snapshots[next_] - 1e-9 * model_.dt;
         ++next_) {
      const std::string stem = "snapshot_" + std::to_string(next_);
      write(stem);
      snapshots_ << next_ << ',' << exact_text(scene_.snapshots[next_]) << ','
                 << exact_text(run.time()) << ',' << run.step_count() << ',' << name_ << '/' << stem
                 << ".vtu\n";
    }
  }

  /// Saves or loads the rows, the series' entries and the snapshots taken (a checkpoint).
  void archive(StateArchive& a) {
    history_.archive(a);
    series_.archive(a);
    a.value("outputs.next_snapshot", next_);
    std::string taken = snapshots_.str();
    a.text("outputs.snapshots", taken);
    if (a.loading()) snapshots_.str(taken), snapshots_.seekp(0, std::ios::end);
  }

  /// The history's last rows and the snapshots' list.
  void finish() {
    history_.flush();
    if (scene_.snapshots.empty()) return;
    fs::create_directories(out_ / "snapshots");
    write_file_atomically(out_ / "snapshots" / (name_ + ".csv"), snapshots_.str());
  }

 private:
  fs::path write(const std::string& stem) {
    const fs::path file = out_ / "vtu" / name_ / (stem + ".vtu");
    fs::create_directories(file.parent_path());
    write_frame(file, model_.mesh(), *model_.run, model_.integrator, model_.strain,
                model_.variation.stiffness,
                model_.cracks ? model_.cracks->cell_fields(model_.mass) : std::vector<VtuField>{});
    return file;
  }

  const ExplicitSimulation& model_;
  const DynamicsScene& scene_;
  const fs::path out_;
  const std::string name_;
  DynamicsHistory history_;
  PvdCollection series_;
  std::size_t next_ = 0;  // the next snapshot
  std::ostringstream snapshots_;
};

/// One run's simulation with what observes and writes it: built whole, and again whole when a
/// checkpoint is refused half-way through its load.
struct RunParts {
  RunParts(const DynamicsScene& scene, const EnsembleRunId& id, const fs::path& out)
      : model(dynamics_simulation(scene, id)),
        outputs(model, scene, out, id.id()),
        probe(scene, *scene.problem, model.bodies, *model.run, scene.output_every) {
    if (model.cracks) probe.watch_cracks(model.cracks->cohesive());
  }
  /// Everything the next step reads or the end of the run reports.
  void archive(StateArchive& a) {
    model.archive(a);
    probe.archive(a);
    outputs.archive(a);
  }

  ExplicitSimulation model;
  RunOutputs outputs;
  DynamicsProbe probe;
};

/// Steps the model from step `first` to its end, observing and writing as the scene asks, with
/// a checkpoint when one is due or a stop is asked for. Throws NumericalError once the run is
/// unstable (ExplicitSimulation::unstable), Interrupted after a stop's checkpoint.
void time_loop(RunParts& parts, const DynamicsScene& scene, RunCheckpoints& checkpoints,
               long first) {
  ExplicitSimulation& model = parts.model;
  RunOutputs& outputs = parts.outputs;
  DynamicsProbe& probe = parts.probe;
  CentralDifference& run = *model.run;
  if (first == 0) {
    probe.observe();
    if (model.cracks) model.cracks->check_balance(run.record());
    outputs.record(run.record());
    outputs.frame();
    outputs.snapshots();
  }
  const auto save = [&](StateArchive& a) { parts.archive(a); };
  for (long s = first + 1; s <= model.steps; ++s) {
    model.step();
    const StepRecord& step = run.record();
    probe.observe();
    const bool unstable = model.unstable();
    const bool last = s == model.steps || unstable;
    if (s % scene.history_every == 0 || last) {
      outputs.record(step);
      if (model.cracks) model.cracks->check_balance(step);
    }
    if (s % scene.output_every == 0 || last) {
      probe.observe_rotation();
      outputs.flush();
      if (!unstable) outputs.frame();  // a blown-up state has no picture worth drawing
    }
    if (!unstable) outputs.snapshots();
    if (unstable)
      throw NumericalError("unstable at step " + std::to_string(s) + " (t = " + fmt(step.time) +
                           " s): the energy grew to " + fmt(model.energy_growth(), 3) +
                           " times the input (dt = " + fmt(scene.safety) + " x the " +
                           step_estimate_name(scene.estimate) + " estimate)");
    if (last) break;
    stop_if_requested(checkpoints, s, step.time, save);
    if (checkpoints.due(s)) checkpoints.write(s, step.time, save);
  }
}

}  // namespace

void check_dynamics_meshes(const DynamicsScene& scene, const std::vector<EnsembleRunId>& runs) {
  check_each_level(
      runs, [&](const EnsembleRunId& run) { bodies_mesh(scene, run); },
      "scene " + scene.path.string() + ": ");
}

ExplicitSimulation dynamics_simulation(const DynamicsScene& scene, const EnsembleRunId& id) {
  return ExplicitSimulation(scene, bodies_mesh(scene, id), *scene.problem, id.seed, id.realization);
}

DynamicsRecord run_dynamics(const DynamicsScene& scene, const EnsembleRunId& id,
                            const fs::path& out,
                            const std::function<void(const ExplicitSimulation&)>& at_end) {
  const Stopwatch clock;
  auto parts = std::make_unique<RunParts>(scene, id, out);
  // A part of a study differs from its siblings by its label and its step fraction.
  const std::string part = scene.label + "@" + exact_text(scene.step_fraction);
  RunCheckpoints checkpoints(
      out, checkpoint_owner(scene.settings, part, parts->model.mesh(), id.id()), scene.checkpoint);
  // What the record describes is the run as built, at t = 0 (a resumed map has split).
  DynamicsRecord r;
  r.run = id;
  const ExplicitSimulation& built = parts->model;
  r.cells = built.mesh().num_cells();
  r.h_avg = built.bodies.h_avg;
  r.dt_lanczos = built.dt_lanczos, r.dt_cells = built.dt_cells;
  r.lanczos_iterations = built.lanczos_iterations;
  r.dt = built.dt;
  r.steps = built.steps;
  r.contact_stiffness = built.contact_stiffness;
  r.dofs = built.run->dofs().num_dofs();
  const std::optional<long> resumed =
      checkpoints.resume([&](StateArchive& a) { parts->archive(a); },
                         [&] { parts = std::make_unique<RunParts>(scene, id, out); });
  ExplicitSimulation& model = parts->model;
  const double setup = clock.seconds();
  try {
    time_loop(*parts, scene, checkpoints, resumed.value_or(0));
    r.complete = true;
  } catch (const NumericalError& e) {  // unstable, or a breakdown: what was written stays
    r.failure = e.what();
  }
  parts->outputs.finish();
  r.steps = model.run->step_count();  // those done: fewer if the run stopped
  r.end_time = model.run->time();
  r.measures = parts->probe.finish();
  parts->probe.write(out, id.id());
  if (model.cracks) record_fragments(*model.cracks, scene, model.mass, out, id.id(), r.measures);
  if (model.coupling) r.measures.coupling_seconds = model.run->coupling_seconds();
  r.checkpoints = checkpoints.written();
  r.checkpoint_seconds = checkpoints.seconds();
  r.seconds = clock.seconds();
  r.loop_seconds = r.seconds - setup;
  if (at_end) at_end(model);
  checkpoints.finished();
  return r;
}

}  // namespace vorodg
