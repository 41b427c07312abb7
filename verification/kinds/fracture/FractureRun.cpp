#include "verification/kinds/fracture/FractureRun.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/element/ElasticityIntegrator.hpp"
#include "core/element/ElementTable.hpp"
#include "core/io/AtomicFile.hpp"
#include "core/io/PvdCollection.hpp"
#include "core/io/StateArchive.hpp"
#include "core/io/VtuMesh.hpp"
#include "core/mesh/MeshValidator.hpp"
#include "core/random/MaterialVariation.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "core/util/Stopwatch.hpp"
#include "dg/CohesiveFracture.hpp"
#include "dg/QuasiStaticPath.hpp"
#include "verification/report/ConvergenceTable.hpp"

namespace fs = std::filesystem;

namespace vorodg {
namespace {

constexpr int kCurveWriteEvery = 10;  // points between rewrites of a run's curve file

/// The deformed mesh as disconnected cells (every cell its own vertex copies, moved by `scale`
/// times the displacement), with each cell's worst interface state: 0 intact, 1 cohesive, 2 open.
void write_deformed(const fs::path& path, const CohesiveFracture& model, const Eigen::VectorXd& u,
                    const std::vector<InterfacePoint>& points, double scale) {
  const PolygonMesh& mesh = model.space().mesh();
  std::vector<Point> vertices;
  std::vector<int> offsets{0}, loops;
  VtuField displacement{"displacement", 2, {}};
  VtuField state{"interface_state", 1, model.cell_interface_states(points)};
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto loop = mesh.cell_vertices(c);
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const int dof = model.space().dof(c, static_cast<int>(k));
      const Eigen::Vector2d d(u[dof], u[dof + 1]);
      loops.push_back(static_cast<int>(vertices.size()));
      vertices.push_back(mesh.vertex(loop[k]) + scale * d);
      displacement.values.push_back(d.x());
      displacement.values.push_back(d.y());
    }
    offsets.push_back(static_cast<int>(loops.size()));
  }
  const PolygonMesh exploded(mesh.domain(), std::move(vertices), std::move(offsets),
                             std::move(loops));
  write_vtu(path, exploded, {{displacement}, {state}});
}

/// Faces past the strength (softening or open; not the notch) as segments x0,y0,x1,y1,state.
std::string crack_faces(const CohesiveFracture& model, const std::vector<InterfacePoint>& points) {
  ColumnStyle number, text;
  number.csv_precision = 12, text.csv_quoted = false;
  ConvergenceTable t;
  for (const char* c : {"x0", "y0", "x1", "y1"}) t.declare_column(c, number);
  t.declare_column("state", text);
  for (const CrackedFace& f : model.cracked_faces(points)) {
    t.start_row();
    for (const auto& [column, value] :
         {std::pair{"x0", f.a.x()}, {"y0", f.a.y()}, {"x1", f.b.x()}, {"y1", f.b.y()}})
      t.add_value(column, value);
    t.add_text("state", f.open ? "open" : "cohesive");
  }
  return csv_text(t);
}

/// Total length over extent along y of the cracked faces (NaN for none, or none with extent).
double tortuosity(const std::vector<CrackedFace>& faces) {
  double length = 0.0, low = HUGE_VAL, high = -HUGE_VAL;
  for (const CrackedFace& f : faces) {
    length += (f.b - f.a).norm();
    low = std::min({low, f.a.y(), f.b.y()}), high = std::max({high, f.a.y(), f.b.y()});
  }
  return high > low ? length / (high - low) : NAN;
}

}  // namespace

GeneratedMesh fracture_run_mesh(const FractureScene& scene, const EnsembleRunId& run) {
  GeneratedMesh generated = generate_mesh(fracture_mesh_spec(
      scene.meshes[run.mesh].spec(scene.geometry.domain, run.level, run.seed), scene.geometry));
  if (const auto report = validate_mesh(generated.mesh); !report.ok())
    throw NumericalError("invalid mesh: " + report.defects.front().what);
  return generated;
}

namespace {

/// What a run keeps of each converged point of its path: a row of its curve (rewritten every
/// kCurveWriteEvery points, so a stopped run keeps a whole file), the record's running figures
/// (peak, dissipation, balance, the bar's closed form), and every vtu_every points a frame.
class PathRecorder {
 public:
  PathRecorder(const FractureScene& scene, const CohesiveFracture& model,
               const IsotropicElasticity& material, const fs::path& out, std::string id,
               FractureRecord& record)
      : scene_(scene),
        model_(model),
        material_(material),
        out_(out),
        id_(std::move(id)),
        r_(record),
        curve_file_(out / "curves" / (id_ + ".csv")),
        series_(out / "vtu" / (id_ + ".pvd")),
        // Displacements are tiny against the body: magnify them to a twentieth of its size.
        magnify_(0.05 * scene.geometry.domain.scale() /
                 std::max(scene.loading.max_stroke, scene.loading.max_cmod)) {
    fs::create_directories(out / "curves");
    fs::create_directories(out / "cracks");
    curve_ << "step,displacement,cmod,load,external_work,elastic_energy,dissipated_energy,"
              "coupling_energy,cohesive_energy,switched_energy,crack_length,inserted,newton_"
              "iterations\n";
  }

  void operator()(const PathPoint& p, const Eigen::VectorXd& u,
                  const std::vector<InterfacePoint>& points) {
    curve_ << p.step << ',' << fmt(p.stroke, 12) << ',' << fmt(p.cmod, 12) << ',' << fmt(p.load, 12)
           << ',' << fmt(p.external_work, 12) << ',' << fmt(p.energy.elastic, 12) << ','
           << fmt(p.energy.dissipated, 12) << ',' << fmt(p.energy.coupling, 12) << ','
           << fmt(p.energy.cohesive, 12) << ',' << fmt(p.energy.switched, 12) << ','
           << fmt(p.energy.crack_length, 12) << ',' << p.inserted << ',' << p.iterations << '\n';
    update_record(p);
    if (scene_.vtu_every > 0 && p.step % scene_.vtu_every == 0) {
      const fs::path file = out_ / "vtu" / id_ / ("step_" + std::to_string(p.step) + ".vtu");
      fs::create_directories(file.parent_path());
      write_deformed(file, model_, u, points, magnify_);
      series_.add(p.stroke, fs::absolute(file));  // listed relative to the .pvd, whatever -o was
    }
    last_points_ = points;
    if (p.step % kCurveWriteEvery == 0) write_file_atomically(curve_file_, curve_.str());
  }

  /// Saves or loads the curve, the series, the last point's states and the record's running
  /// figures (a checkpoint).
  void archive(StateArchive& a) {
    a.text("recorder.curve", curve_);
    series_.archive(a);
    a.vector("recorder.last_points", last_points_);
    for (double* x : {&r_.peak_load, &r_.displacement_at_peak, &r_.dissipated_energy,
                      &r_.crack_length, &r_.energy_balance_error, &r_.closed_form_error,
                      &r_.load_at_twice_peak, &previous_stroke_, &previous_load_})
      a.value("recorder.figure", *x);
    a.value("recorder.newton_iterations", r_.newton_iterations);
    a.value("recorder.points", r_.points);
  }

  /// The whole curve, and the faces past the strength at the last point.
  void finish() {
    r_.crack_tortuosity = tortuosity(model_.cracked_faces(last_points_));
    write_file_atomically(curve_file_, curve_.str());
    write_file_atomically(out_ / "cracks" / (id_ + ".csv"), crack_faces(model_, last_points_));
  }

 private:
  void update_record(const PathPoint& p) {
    if (p.load > r_.peak_load) {  // a new peak: the softening branch starts again
      r_.peak_load = p.load, r_.displacement_at_peak = p.stroke;
      r_.load_at_twice_peak = NAN;
    } else if (std::isnan(r_.load_at_twice_peak) && p.stroke >= 2.0 * r_.displacement_at_peak &&
               r_.displacement_at_peak > 0.0) {
      const double target = 2.0 * r_.displacement_at_peak;
      const double t = p.stroke > previous_stroke_
                           ? (target - previous_stroke_) / (p.stroke - previous_stroke_)
                           : 1.0;
      r_.load_at_twice_peak = previous_load_ + std::clamp(t, 0.0, 1.0) * (p.load - previous_load_);
    }
    previous_stroke_ = p.stroke, previous_load_ = p.load;
    r_.dissipated_energy = p.energy.dissipated;
    r_.crack_length = p.energy.crack_length;
    r_.energy_balance_error = std::max(r_.energy_balance_error, p.balance_error());
    if (const std::optional<double> d = scene_.geometry.problem->closed_form_deviation(
            scene_.geometry, material_, model_.interfaces().law(), scene_.thickness, p.stroke,
            p.cmod, p.load))
      r_.closed_form_error =
          std::isnan(r_.closed_form_error) ? *d : std::max(r_.closed_form_error, *d);
    r_.newton_iterations += p.iterations;
    ++r_.points;
  }

  const FractureScene& scene_;
  const CohesiveFracture& model_;
  const IsotropicElasticity& material_;
  const fs::path out_;
  const std::string id_;
  FractureRecord& r_;
  const fs::path curve_file_;
  PvdCollection series_;
  const double magnify_;
  std::ostringstream curve_;
  std::vector<InterfacePoint> last_points_;
  double previous_stroke_ = 0.0, previous_load_ = 0.0;  // the point before, to interpolate
};

}  // namespace

void check_fracture_meshes(const FractureScene& scene, const std::vector<EnsembleRunId>& runs) {
  check_each_level(
      runs,
      [&](const EnsembleRunId& run) {
        fracture_setup(fracture_run_mesh(scene, run).mesh, scene.geometry, scene.mode,
                       scene.thickness);
      },
      "");
}

FractureRecord run_fracture(const FractureScene& scene, const EnsembleRunId& run,
                            const fs::path& out, const FracturePathObserver& observe) {
  const Stopwatch clock;
  FractureRecord r;
  r.run = run;
  const GeneratedMesh generated = fracture_run_mesh(scene, run);
  const PolygonMesh& mesh = generated.mesh;
  r.cells = mesh.num_cells();
  r.full_dg_dofs = 2 * mesh.offsets().back();
  r.h_avg = mesh.h_avg();
  const ElementTable table(mesh, scene.element);
  const IsotropicElasticity material(scene.E, scene.nu, scene.plane);
  const ElasticityIntegrator integrator(table, material, false);
  FractureSetup setup = fracture_setup(mesh, scene.geometry, scene.mode, scene.thickness);
  setup.split_all = scene.split_all;
  CohesiveParameters law = scene.law;
  if (scene.mode == CrackingMode::pre_inserted)
    law.initial_stiffness = scene.initial_stiffness * scene.E / mesh.h_avg();
  CohesiveFracture model(table, integrator, setup, law, scene.criterion, DgOptions{});
  if (scene.field.enabled)  // realization i's strength, the same field on every level
    model.set_edge_strength(
        MaterialVariation::from_field(mesh, scene.field, run.realization).edge_strength(mesh));
  model.setup_system();
  r.dofs = model.num_dofs();

  const double setup_seconds = clock.seconds();
  // The path and its recorder are all that changes along the path (the model is rebuilt
  // identically from the scene); built again whole if a checkpoint is refused half-way through
  // its load.
  struct PathParts {
    PathRecorder recorder;
    QuasiStaticPath path;
  };
  const FractureRecord blank = r;
  auto build = [&] {
    r = blank;
    return std::unique_ptr<PathParts>(
        new PathParts{PathRecorder(scene, model, material, out, run.id(), r),
                      QuasiStaticPath(model, scene.loading)});
  };
  std::unique_ptr<PathParts> parts = build();
  const auto save = [&](StateArchive& a) {
    parts->path.archive(a);
    parts->recorder.archive(a);
  };
  RunCheckpoints checkpoints(out, checkpoint_owner(scene.settings, "", mesh, run.id()),
                             scene.checkpoint);
  checkpoints.set_clock("stroke", "m");
  checkpoints.resume(save, [&] { parts = build(); });
  QuasiStaticPath& path = parts->path;
  PathRecorder& recorder = parts->recorder;
  r.complete = path.run(
      [&](const PathPoint& p, const Eigen::VectorXd& u, const std::vector<InterfacePoint>& points) {
        recorder(p, u, points);
        if (observe) observe(model, p, points);
      },
      [&](int step) {  // the checkpoint's clock is the stroke
        stop_if_requested(checkpoints, step, path.last().stroke, save);
        if (checkpoints.due(step)) checkpoints.write(step, path.last().stroke, save);
      });
  recorder.finish();
  checkpoints.finished();
  r.failure = path.failure();
  r.ended = path.stop_reason();
  r.factorizations = path.factorizations();
  r.seconds = clock.seconds();
  r.path_seconds = r.seconds - setup_seconds;
  return r;
}

}  // namespace vorodg
