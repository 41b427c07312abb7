#include "verification/kinds/dynamics/DynamicsModel.hpp"

#include <cmath>
#include <numbers>

#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "core/util/Random.hpp"
#include "dynamics/GlobalTimeStep.hpp"
#include "dynamics/StableTimeStep.hpp"

namespace vorodg {
namespace {

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

}  // namespace

DynamicsModel::DynamicsModel(const DynamicsScene& s, const EnsembleRunId& id)
    : scene(s),
      bodies(bodies_mesh(s, id)),
      table(bodies.mesh, s.element),
      mass(table, s.density),
      integrator(table, IsotropicElasticity(s.E, s.nu, s.plane), s.mean_dilation),
      strain(integrator.all_mean_strain_operators(1)),
      // A material varying from cell to cell (each mesh realization its own field).
      variation(MaterialVariation::uniform(bodies.mesh.num_cells(), s.variation,
                                           derive_seed(s.variation_seed, id.seed))) {
  const SplitDofMap dofs = SplitDofMap::continuous(mesh());
  InternalForce force = make_force(dofs);
  make_integrator(std::move(force), dofs);
}

InternalForce DynamicsModel::make_force(const SplitDofMap& dofs) {
  auto matrices = integrator.all_cell_matrices(1);
  if (!variation.empty())
    for (int c = 0; c < mesh().num_cells(); ++c)
      for (std::size_t i = matrices.offset[c]; i < matrices.offset[c + 1]; ++i)
        matrices.data[i] *= variation.stiffness[c];
  const StableTimeStep bound(mesh(), matrices, mass);
  InternalForce force(mesh(), std::move(matrices));
  const GlobalTimeStep lanczos(force, dofs, mass.node_masses(dofs),
                               bound);  // of K: the linear force
  dt_lanczos = lanczos.critical();
  dt_cells = bound.critical();
  lanczos_iterations = lanczos.iterations();
  // safety x the chosen estimate; >= 1 only got here with --force. With cracks, the cells' bound
  // (valid for every split) and the cohesive springs' share.
  if (scene.fragmentation) cracks.emplace(scene, mesh(), bodies.h_avg);
  dt = cracks ? cracks->stable_step(bound, mass, scene.safety)
              : scene.safety * (scene.estimate == StepEstimate::lanczos ? dt_lanczos : dt_cells);
  steps = scene.steps > 0 ? scene.steps : static_cast<long>(std::ceil(scene.end / dt - 1e-9));
  if (!scene.corotational) return force;
  // The same cells, each turning with its frame (K is its tangent at rest).
  return InternalForce(mesh(), force.matrices(), true);
}

void DynamicsModel::make_integrator(InternalForce force, const SplitDofMap& dofs) {
  run.emplace(mesh(), mass, std::move(force), dofs, dt, DynamicsOptions{scene.damping, 1});
  contact.emplace(mesh(), PenaltyContact(scene.penalty), scene.contact);
  if (scene.wall) contact->add_plane(scene.wall->point, scene.wall->normal);
  if (scene.contact || scene.wall) run->set_contact(*contact);
  add_boundaries(scene, mesh(), *run);
  if (cracks) cracks->attach(*run, integrator, variation, scene.contact ? &*contact : nullptr, 1);
  run->initialize(Eigen::VectorXd::Zero(run->dofs().num_dofs()),
                  initial_velocity(scene, bodies, *run));
}

}  // namespace vorodg
