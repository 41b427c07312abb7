#include "verification/kinds/dynamics/DynamicsModel.hpp"

#include <cmath>

#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "core/util/Random.hpp"
#include "dynamics/GlobalTimeStep.hpp"
#include "dynamics/StableTimeStep.hpp"

namespace vorodg {
namespace {

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
    scene.problem->add_initial_velocity(b, run.node_position(i), v.segment<2>(2 * i));
  }
  return v;
}

/// Where a fragmentation run's cracks are and may form (none for a dynamics study).
CrackSites crack_sites(const DynamicsScene& scene, const PolygonMesh& mesh) {
  return scene.fragmentation ? scene.problem->crack_sites(mesh) : CrackSites{};
}

/// The nodes at t = 0: one per vertex, split along the faces there from the start (a notch, a
/// pre-inserted crack line; FragmentationRun gives them their tractions), and with interfaces
/// coupled from the start along every edge that may crack too (every interior edge of a
/// dynamics study).
SplitDofMap initial_dofs(const DynamicsScene& scene, const PolygonMesh& mesh,
                         const CrackSites& sites) {
  if (scene.dg_interfaces && (!scene.fragmentation || sites.eligible.empty()))
    return SplitDofMap::discontinuous(mesh);
  std::vector<char> connected(mesh.num_edges(), 1);
  if (scene.dg_interfaces)
    for (int e = 0; e < mesh.num_edges(); ++e) connected[e] = !sites.eligible[e];
  for (const std::vector<int>* edges : {&sites.pre_inserted, &sites.free})
    for (int e : *edges) connected[e] = 0;
  return SplitDofMap(mesh, connected);
}

/// Gravity, and the problem's prescribed velocities and loads.
void add_boundaries(const DynamicsScene& scene, const PolygonMesh& mesh, CentralDifference& run) {
  if (scene.gravity != Eigen::Vector2d::Zero()) {
    const Eigen::Vector2d g = scene.gravity;
    run.set_body_force([g](double) { return g; });
  }
  scene.problem->add_boundaries(mesh, run);
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
  const CrackSites sites = crack_sites(s, mesh());
  const SplitDofMap dofs = initial_dofs(s, mesh(), sites);
  InternalForce force = make_force(dofs, sites);
  make_integrator(std::move(force), dofs);
}

InternalForce DynamicsModel::make_force(const SplitDofMap& dofs, const CrackSites& sites) {
  auto matrices = integrator.all_cell_matrices(1);
  if (!variation.empty())
    for (int c = 0; c < mesh().num_cells(); ++c)
      for (std::size_t i = matrices.offset[c]; i < matrices.offset[c + 1]; ++i)
        matrices.data[i] *= variation.stiffness[c];
  const StableTimeStep bound(mesh(), matrices, mass);
  if (scene.dg_interfaces) {
    coupling.emplace(table, integrator, matrices, dofs);
    // The faces there from t = 0 are cracks or a notch, never coupled.
    for (const std::vector<int>* edges : {&sites.pre_inserted, &sites.free})
      for (int e : *edges) coupling->deactivate(coupling->interface_of_edge(e));
  }
  InternalForce force(mesh(), std::move(matrices));
  if (scene.fragmentation) cracks.emplace(scene, mesh(), bodies.h_avg);
  if (cracks && coupling && scene.interface_closure) cracks->close_as_interfaces(*coupling);
  // The cells' bound (valid for every split), plus the coupled interfaces' and, with cracks, the
  // faces' springs': with cracks it holds for every crack pattern the run can reach.
  const double coupled = coupling ? coupling->eigenvalue_bound(mass.node_masses(dofs)) : 0.0;
  const double cap =
      cracks ? cracks->eigenvalue_bound(bound, mass, coupled) : bound.max_eigenvalue() + coupled;
  dt_cells = 2.0 / std::sqrt(cap);
  // The Lanczos estimate of K (the linear force): with cracks (and no coupling), of the cells and
  // springs on the map split wherever a face may form, which holds for every crack pattern too;
  // otherwise of the map at t = 0.
  const GlobalTimeStep lanczos = cracks && !coupling
                                     ? cracks->estimated_step(force, mass, cap)
                                     : GlobalTimeStep(force, dofs, mass.node_masses(dofs), bound,
                                                      {}, coupling ? &*coupling : nullptr);
  dt_lanczos = lanczos.critical();
  lanczos_iterations = lanczos.iterations();
  // safety x the chosen estimate; >= 1 only got here with --force.
  dt = scene.safety * (scene.estimate == StepEstimate::lanczos ? dt_lanczos : dt_cells);
  // Bulk viscosity's linear term damps the highest mode by xi = b1, which lowers the critical
  // step by sqrt(1 + b1^2) - b1; its quadratic term is checked step by step against what is
  // left (BulkViscosity::set_step_ratio). The plastic contact penalty lowers it by 1 / sqrt(2)
  // (PenaltyContact::step_factor).
  const double factor =
      (scene.bulk_viscosity.linear > 0.0 ? BulkViscosity::step_factor(scene.bulk_viscosity.linear)
                                         : 1.0) *
      PenaltyContact(scene.penalty).step_factor();
  dt *= factor;
  bulk_step_ratio = scene.safety * factor;
  steps = scene.steps > 0 ? scene.steps : static_cast<long>(std::ceil(scene.end / dt - 1e-9));
  if (!scene.corotational) return force;
  // The same cells, each turning with its frame (K is its tangent at rest).
  return InternalForce(mesh(), force.matrices(), true);
}

std::vector<double> DynamicsModel::wave_speeds() const {
  std::vector<double> speeds(mesh().num_cells(), scene.dilatational_speed());
  if (!variation.empty())
    for (int c = 0; c < mesh().num_cells(); ++c) speeds[c] *= std::sqrt(variation.stiffness[c]);
  return speeds;
}

void DynamicsModel::make_integrator(InternalForce force, const SplitDofMap& dofs) {
  run.emplace(mesh(), mass, std::move(force), dofs, dt, DynamicsOptions{scene.damping, 1});
  if (coupling) run->set_interface_coupling(*coupling);
  PenaltyParameters penalty = scene.penalty;
  if (scene.quiescent_penetration > 0.0) {
    // The report's choice: the whole resting weight on one vertex sinks it x h_avg at most.
    const double weight = mass.total() * std::abs(scene.gravity.dot(scene.wall->normal));
    penalty.stiffness = weight / (scene.quiescent_penetration * bodies.h_avg);
  }
  contact_stiffness = penalty.stiffness > 0.0 ? penalty.stiffness : NAN;
  contact.emplace(mesh(), PenaltyContact(penalty), scene.contact,
                  ContactFriction(scene.contact_friction, "contact.friction"));
  if (scene.wall)
    contact->add_plane(scene.wall->point, scene.wall->normal,
                       ContactFriction(scene.wall->friction, "wall.friction"));
  if (scene.contact || scene.wall) run->set_contact(*contact);
  add_boundaries(scene, mesh(), *run);
  if (scene.bulk_viscosity.active()) {
    bulk.emplace(mesh(), scene.bulk_viscosity, scene.density, wave_speeds());
    bulk->set_step_ratio(bulk_step_ratio);
    bulk->set_current_configuration(scene.corotational);
    run->set_bulk_viscosity(*bulk);
  }
  if (cracks)
    cracks->attach(*run, integrator, variation, scene.contact ? &*contact : nullptr, 1,
                   coupling ? &*coupling : nullptr);
  run->initialize(Eigen::VectorXd::Zero(run->dofs().num_dofs()),
                  initial_velocity(scene, bodies, *run));
}

}  // namespace vorodg
