#include "verification/dynamics/DynamicsRun.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>

#include "core/element/ElasticityIntegrator.hpp"
#include "core/element/ElementTable.hpp"
#include "core/io/AtomicFile.hpp"
#include "core/io/PvdCollection.hpp"
#include "core/io/VtuMesh.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "core/util/Random.hpp"
#include "core/util/Stopwatch.hpp"
#include "dynamics/CentralDifference.hpp"
#include "dynamics/ContactForces.hpp"
#include "dynamics/GlobalTimeStep.hpp"
#include "dynamics/LumpedMass.hpp"
#include "dynamics/MaterialVariation.hpp"
#include "dynamics/StableTimeStep.hpp"
#include "verification/dynamics/DynamicsHistory.hpp"
#include "verification/dynamics/FragmentationRun.hpp"
#include "verification/model/SettingsSchema.hpp"

namespace fs = std::filesystem;

namespace vorodg {
namespace {

/// The run stops as unstable once kinetic plus elastic energy exceeds this many times the energy
/// put in: a stable run stays within round-off of its input.
constexpr double kBlowUp = 1e6;

/// The wave bar's input: a (1 - cos) rise, a hold and a (1 + cos) fall, a third of `duration`
/// each, so that the velocity and its rate start and end at zero.
double pulse(double t, double amplitude, double duration) {
  const double tr = duration / 3.0;
  if (t <= 0.0 || t >= duration) return 0.0;
  if (t < tr) return amplitude * 0.5 * (1.0 - std::cos(std::numbers::pi * t / tr));
  if (t < 2.0 * tr) return amplitude;
  return amplitude * 0.5 * (1.0 + std::cos(std::numbers::pi * (t - 2.0 * tr) / tr));
}

/// Each body's uniform velocity plus its spin about its own centre of mass.
Eigen::VectorXd initial_velocity(const DynamicsScene& scene, const BodiesMesh& bodies,
                                 const CentralDifference& run) {
  const int nodes = run.dofs().num_nodes();
  std::vector<int> body(nodes, 0);
  for (int c = 0; c < bodies.mesh.num_cells(); ++c)
    for (int k = 0; k < bodies.mesh.cell_size(c); ++k)
      body[run.dofs().node(c, k)] = bodies.body_of_cell(c);
  std::vector<Point> centre(scene.bodies.size(), Point::Zero());
  std::vector<double> mass(scene.bodies.size(), 0.0);
  for (int i = 0; i < nodes; ++i) {
    centre[body[i]] += run.node_masses()[i] * run.node_position(i);
    mass[body[i]] += run.node_masses()[i];
  }
  Eigen::VectorXd v(2 * nodes);
  for (int i = 0; i < nodes; ++i) {
    const DynamicsBody& b = scene.bodies[body[i]];
    const Point r = run.node_position(i) - centre[body[i]] / mass[body[i]];
    v.segment<2>(2 * i) = b.velocity + b.angular_velocity * Point(-r.y(), r.x());
    if (scene.problem == DynamicsProblem::strip_expansion)  // stretched about the middle
      v[2 * i] +=
          scene.strain_rate * (run.node_position(i).x() - 0.5 * (b.domain.x0() + b.domain.x1()));
  }
  return v;
}

/// projectile-impact: the top vertices under the projectile's nose move down at its speed.
void add_projectile(const DynamicsProjectile& p, const PolygonMesh& mesh, CentralDifference& run) {
  std::vector<int> under;
  for (int v : mesh.side_vertices(Side::top))
    if (std::abs(mesh.vertex(v).x() - p.position) <= 0.5 * p.width) under.push_back(v);
  if (under.empty())
    throw InputError("projectile: no vertex of the top side within its nose [" +
                     fmt(p.position - 0.5 * p.width) + ", " + fmt(p.position + 0.5 * p.width) +
                     "]: expected a nose wider than the cells");
  const double speed = p.speed;
  run.add_velocity_boundary({under, 1, [speed](double) { return -speed; }});
}

void add_boundaries(const DynamicsScene& scene, const PolygonMesh& mesh, CentralDifference& run) {
  if (scene.gravity != Eigen::Vector2d::Zero()) {
    const Eigen::Vector2d g = scene.gravity;
    run.set_body_force([g](double) { return g; });
  }
  if (scene.projectile) add_projectile(*scene.projectile, mesh, run);
  if (scene.problem != DynamicsProblem::wave_bar) return;
  const double amplitude = scene.pulse_amplitude, duration = scene.pulse_duration;
  run.add_velocity_boundary(
      {mesh.side_vertices(Side::left), 0, [=](double t) { return pulse(t, amplitude, duration); }});
  if (scene.rollers)
    for (Side s : {Side::bottom, Side::top})
      run.add_velocity_boundary({mesh.side_vertices(s), 1, [](double) { return 0.0; }});
}

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
  const IsotropicElasticity& m = integrator.material();
  const CorotationalFrames* frames = run.force().frames();
  for (int c = 0; c < mesh.num_cells(); ++c) {
    Eigen::VectorXd uc(2 * mesh.cell_size(c));
    CorotationalFrames::Turn turn;  // none for small rotations
    if (frames)
      turn = frames->local_displacements(c, run.dofs(), run.displacement(), uc);
    else
      for (int k = 0; k < mesh.cell_size(c); ++k)
        uc.segment<2>(2 * k) = run.displacement().segment<2>(2 * run.dofs().node(c, k));
    const Eigen::Vector3d s = CorotationalFrames::global_stress(
        turn, (stiffness.empty() ? 1.0 : stiffness[c]) * (m.D() * (strain.block(c) * uc)));
    const double sz = m.model() == PlaneModel::strain ? m.nu() * (s[0] + s[1]) : 0.0;
    stress.values.insert(stress.values.end(), {s[0], s[1], s[2]});
    von_mises.values.push_back(
        std::sqrt(0.5 * ((s[0] - s[1]) * (s[0] - s[1]) + (s[1] - sz) * (s[1] - sz) +
                         (sz - s[0]) * (sz - s[0])) +
                  3.0 * s[2] * s[2]));
  }
  cell_fields.insert(cell_fields.begin(), {stress, von_mises});
  // The frame's domain is the deformed bounding box (the bodies have moved off the reference one).
  Point lo = moved.front(), hi = moved.front();
  for (const Point& p : moved) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const PolygonMesh deformed(Rectangle(lo.x(), lo.y(), hi.x(), hi.y()), moved, mesh.offsets(),
                             cells);
  write_vtu(file, deformed, {{displacement, velocity}, cell_fields});
}

}  // namespace

void check_dynamics_meshes(const DynamicsScene& scene, const std::vector<EnsembleRunId>& runs) {
  check_each_level(
      runs, [&](const EnsembleRunId& run) { bodies_mesh(scene, run); },
      "scene " + scene.path.string() + ": ");
}

DynamicsRecord run_dynamics(const DynamicsScene& scene, const EnsembleRunId& id,
                            const fs::path& out) {
  Stopwatch clock;
  DynamicsRecord r;
  r.run = id;
  const BodiesMesh bodies = bodies_mesh(scene, id);
  const PolygonMesh& mesh = bodies.mesh;
  r.cells = mesh.num_cells();
  r.h_avg = bodies.h_avg;
  const ElementTable table(mesh, scene.element);
  const LumpedMass mass(table, scene.density);
  const ElasticityIntegrator integrator(table, IsotropicElasticity(scene.E, scene.nu, scene.plane),
                                        scene.mean_dilation);
  const auto strain = integrator.all_mean_strain_operators(1);
  auto matrices = integrator.all_cell_matrices(1);
  // A material varying from cell to cell (each mesh realization its own field).
  const MaterialVariation variation = MaterialVariation::uniform(
      mesh.num_cells(), scene.variation, derive_seed(scene.variation_seed, id.seed));
  if (!variation.empty())
    for (int c = 0; c < mesh.num_cells(); ++c)
      for (std::size_t i = matrices.offset[c]; i < matrices.offset[c + 1]; ++i)
        matrices.data[i] *= variation.stiffness[c];
  const StableTimeStep bound(mesh, matrices, mass);
  const SplitDofMap dofs = SplitDofMap::continuous(mesh);
  InternalForce force(mesh, std::move(matrices));
  const GlobalTimeStep lanczos(force, dofs, mass.node_masses(dofs),
                               bound);  // of K: the linear force
  r.dt_lanczos = lanczos.critical();
  r.dt_cells = bound.critical();
  r.lanczos_iterations = lanczos.iterations();
  if (scene.corotational) {  // the same cells, each turning with its frame (K is its tangent at
                             // rest)
    InternalForce turning(mesh, force.matrices(), true);
    force = std::move(turning);
  }
  // safety x the chosen estimate; >= 1 only got here with --force. With cracks, the cells' bound
  // (valid for every split) and the cohesive springs' share.
  std::optional<FragmentationRun> cracks;
  if (scene.fragmentation) cracks.emplace(scene, mesh, bodies.h_avg);
  r.dt = cracks
             ? cracks->stable_step(bound, mass, scene.safety)
             : scene.safety * (scene.estimate == StepEstimate::lanczos ? r.dt_lanczos : r.dt_cells);
  r.steps = scene.steps > 0 ? scene.steps : static_cast<long>(std::ceil(scene.end / r.dt - 1e-9));
  CentralDifference run(mesh, mass, std::move(force), dofs, r.dt, {scene.damping, 1});
  r.dofs = run.dofs().num_dofs();
  ContactForces contact(mesh, PenaltyContact(scene.penalty), scene.contact);
  if (scene.wall) contact.add_plane(scene.wall->point, scene.wall->normal);
  if (scene.contact || scene.wall) run.set_contact(contact);
  add_boundaries(scene, mesh, run);
  if (cracks) cracks->attach(run, integrator, variation, scene.contact ? &contact : nullptr, 1);
  run.initialize(Eigen::VectorXd::Zero(run.dofs().num_dofs()),
                 initial_velocity(scene, bodies, run));

  const std::string name = id.id();
  fs::create_directories(out / "history");
  DynamicsHistory history(out / "history" / (name + ".csv"));
  PvdCollection series(out / "vtu" / (name + ".pvd"));
  auto write = [&](const std::string& stem) {
    const fs::path file = out / "vtu" / name / (stem + ".vtu");
    fs::create_directories(file.parent_path());
    write_frame(file, mesh, run, integrator, strain, variation.stiffness,
                cracks ? cracks->cell_fields(mass) : std::vector<VtuField>{});
    return file;
  };
  auto frame = [&] {
    if (scene.vtu) series.add(run.time(), write("step_" + std::to_string(run.step_count())));
  };
  // The snapshots: a frame at the first step at or after each requested time, and their list.
  std::size_t next_snapshot = 0;
  std::ostringstream snapshots;
  snapshots << "snapshot,requested_time,time,step,file\n";
  auto snapshot = [&] {
    for (; next_snapshot < scene.snapshots.size() &&
           run.time() >= scene.snapshots[next_snapshot] - 1e-9 * r.dt;
         ++next_snapshot) {
      const std::string stem = "snapshot_" + std::to_string(next_snapshot);
      write(stem);
      snapshots << next_snapshot << ',' << exact_text(scene.snapshots[next_snapshot]) << ','
                << exact_text(run.time()) << ',' << run.step_count() << ',' << name << '/' << stem
                << ".vtu\n";
    }
  };
  const ContactForces* reports = run.contact();
  DynamicsProbe probe(scene, bodies, run);
  probe.observe();
  if (cracks) cracks->check_balance(run.record());
  history.add(run.record(), reports);
  frame();
  snapshot();
  const double setup = clock.seconds();
  try {
    for (long s = 1; s <= r.steps; ++s) {
      if (cracks)
        cracks->step();
      else
        run.step();
      const StepRecord& step = run.record();
      probe.observe();
      if (cracks) cracks->integrate(step);
      const double energy = step.kinetic + step.elastic;
      const bool unstable = !std::isfinite(energy) || energy > kBlowUp * step.input_energy();
      const bool last = s == r.steps || unstable;
      if (s % scene.history_every == 0 || last) {
        history.add(step, reports);
        if (cracks) cracks->check_balance(step);
      }
      if (s % scene.output_every == 0 || last) {
        probe.observe_rotation();
        history.flush();
        if (!unstable) frame();  // a blown-up state has no picture worth drawing
      }
      if (!unstable) snapshot();
      if (unstable)
        throw NumericalError("unstable at step " + std::to_string(s) + " (t = " + fmt(step.time) +
                             " s): the energy grew to " + fmt(energy / step.input_energy(), 3) +
                             " times the input (dt = " + fmt(scene.safety) + " x the " +
                             step_estimate_name(scene.estimate) + " estimate)");
    }
    r.complete = true;
  } catch (const NumericalError& e) {
    r.failure = e.what();
  }
  history.flush();
  if (!scene.snapshots.empty()) {
    fs::create_directories(out / "snapshots");
    write_file_atomically(out / "snapshots" / (name + ".csv"), snapshots.str());
  }
  r.steps = run.step_count();  // those done: fewer if the run stopped
  r.end_time = run.time();
  r.measures = probe.finish();
  if (cracks) cracks->finish(out, name, mass, r.measures);
  r.seconds = clock.seconds();
  r.loop_seconds = r.seconds - setup;
  return r;
}

}  // namespace vorodg
