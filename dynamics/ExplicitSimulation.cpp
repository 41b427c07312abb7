#include "dynamics/ExplicitSimulation.hpp"

#include <cmath>

#include "core/io/StateArchive.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "core/util/Random.hpp"
#include "dynamics/GlobalTimeStep.hpp"
#include "dynamics/StableTimeStep.hpp"
#include "dynamics/contact/ContactLaws.hpp"

namespace vorodg {
namespace {

/// Each body's uniform velocity plus its spin about its own centre of mass.
Eigen::VectorXd initial_velocity(const ExplicitParameters& p, const ExplicitLoading& loading,
                                 const BodiesMesh& bodies, const CentralDifference& run) {
  const int nodes = run.dofs().num_nodes();
  std::vector<int> body(nodes, 0);
  for (int c = 0; c < bodies.mesh.num_cells(); ++c)
    for (int k = 0; k < bodies.mesh.cell_size(c); ++k)
      body[run.dofs().node(c, k)] = bodies.body_of_cell(c);
  std::vector<Point> centre(p.bodies.size(), Point::Zero());
  std::vector<double> mass(p.bodies.size(), 0.0);
  for (int i = 0; i < nodes; ++i) {
    centre[body[i]] += run.node_masses()[i] * run.node_position(i);
    mass[body[i]] += run.node_masses()[i];
  }
  Eigen::VectorXd v(2 * nodes);
  for (int i = 0; i < nodes; ++i) {
    const DynamicsBody& b = p.bodies[body[i]];
    const Point r = run.node_position(i) - centre[body[i]] / mass[body[i]];
    v.segment<2>(2 * i) = b.velocity + b.angular_velocity * Point(-r.y(), r.x());
    loading.add_initial_velocity(b, run.node_position(i), v.segment<2>(2 * i));
  }
  return v;
}

/// Where a fragmentation run's cracks are and may form (none for a dynamics study).
CrackSites crack_sites(const ExplicitParameters& p, const ExplicitLoading& loading,
                       const PolygonMesh& mesh) {
  return p.fragmentation ? loading.crack_sites(mesh) : CrackSites{};
}

/// The nodes at t = 0: one per vertex, split along the faces there from the start (a notch, a
/// pre-inserted crack line; Fragmentation gives them their tractions), and with interfaces
/// coupled from the start along every edge that may crack too (every interior edge of a
/// dynamics study).
SplitDofMap initial_dofs(const ExplicitParameters& p, const PolygonMesh& mesh,
                         const CrackSites& sites) {
  if (p.dg_interfaces && (!p.fragmentation || sites.eligible.empty()))
    return SplitDofMap::discontinuous(mesh);
  std::vector<char> connected(mesh.num_edges(), 1);
  if (p.dg_interfaces)
    for (int e = 0; e < mesh.num_edges(); ++e) connected[e] = !sites.eligible[e];
  for (const std::vector<int>* edges : {&sites.pre_inserted, &sites.free})
    for (int e : *edges) connected[e] = 0;
  return SplitDofMap(mesh, connected);
}

/// Gravity, and the problem's prescribed velocities and loads.
void add_boundaries(const ExplicitParameters& p, const ExplicitLoading& loading,
                    const PolygonMesh& mesh, CentralDifference& run) {
  if (p.gravity != Eigen::Vector2d::Zero()) {
    const Eigen::Vector2d g = p.gravity;
    run.set_body_force([g](double) { return g; });
  }
  loading.add_boundaries(mesh, run);
}

}  // namespace

ExplicitSimulation::ExplicitSimulation(const ExplicitParameters& s, BodiesMesh bodies_mesh,
                                       const ExplicitLoading& problem, std::uint64_t seed,
                                       int realization)
    : parameters(s),
      loading(problem),
      bodies(std::move(bodies_mesh)),
      table(bodies.mesh, s.element),
      mass(table, s.density),
      integrator(table, IsotropicElasticity(s.E, s.nu, s.plane), s.mean_dilation),
      strain(integrator.all_mean_strain_operators(1)),
      // A material varying from cell to cell: drawn per cell with each mesh realization, or a
      // random field in space that realization `realization` shares across the mesh levels.
      variation(s.field.enabled ? MaterialVariation::from_field(bodies.mesh, s.field, realization)
                                : MaterialVariation::uniform(bodies.mesh.num_cells(), s.variation,
                                                             derive_seed(s.variation_seed, seed))) {
  const CrackSites sites = crack_sites(s, loading, mesh());
  const SplitDofMap dofs = initial_dofs(s, mesh(), sites);
  InternalForce force = make_force(dofs, sites);
  make_integrator(std::move(force), dofs);
}

InternalForce ExplicitSimulation::make_force(const SplitDofMap& dofs, const CrackSites& sites) {
  auto matrices = integrator.all_cell_matrices(1);
  if (!variation.empty())
    for (int c = 0; c < mesh().num_cells(); ++c)
      for (std::size_t i = matrices.offset[c]; i < matrices.offset[c + 1]; ++i)
        matrices.data[i] *= variation.stiffness[c];
  const StableTimeStep bound(mesh(), matrices, mass);
  if (parameters.dg_interfaces) {
    coupling.emplace(table, integrator, matrices, dofs);
    // The faces there from t = 0 are cracks or a notch, never coupled.
    for (const std::vector<int>* edges : {&sites.pre_inserted, &sites.free})
      for (int e : *edges) coupling->deactivate(coupling->interface_of_edge(e));
  }
  InternalForce force(mesh(), std::move(matrices));
  if (parameters.fragmentation) cracks.emplace(parameters, mesh(), bodies.h_avg, sites);
  if (cracks && coupling && parameters.interface_closure) cracks->close_as_interfaces(*coupling);
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
  dt = parameters.safety * (parameters.estimate == StepEstimate::lanczos ? dt_lanczos : dt_cells);
  // Bulk viscosity's linear term damps the highest mode by xi = b1, which lowers the critical
  // step by sqrt(1 + b1^2) - b1; its quadratic term is checked step by step against what is
  // left (BulkViscosity::set_step_ratio). The plastic contact penalty lowers it by 1 / sqrt(2)
  // (PenaltyContact::step_factor), where a penalty law is in use.
  std::vector<std::string> laws;
  if (parameters.contact) laws.push_back(parameters.contact_law);
  if (parameters.wall) laws.push_back(parameters.wall->law);
  const double factor = (parameters.bulk_viscosity.linear > 0.0
                             ? BulkViscosity::step_factor(parameters.bulk_viscosity.linear)
                             : 1.0) *
                        contact_step_factor(laws, PenaltyContact(parameters.penalty));
  dt *= factor;
  bulk_step_ratio = parameters.safety * factor;
  steps = parameters.steps > 0 ? parameters.steps
                               : static_cast<long>(std::ceil(parameters.end / dt - 1e-9));
  if (!parameters.corotational) return force;
  // The same cells, each turning with its frame (K is its tangent at rest).
  return InternalForce(mesh(), force.matrices(), true);
}

std::vector<double> ExplicitSimulation::wave_speeds() const {
  std::vector<double> speeds(mesh().num_cells(), parameters.dilatational_speed());
  if (!variation.empty())
    for (int c = 0; c < mesh().num_cells(); ++c) speeds[c] *= std::sqrt(variation.stiffness[c]);
  return speeds;
}

void ExplicitSimulation::make_integrator(InternalForce force, const SplitDofMap& dofs) {
  run.emplace(mesh(), mass, std::move(force), dofs, dt, DynamicsOptions{parameters.damping, 1});
  if (coupling) run->set_interface_coupling(*coupling);
  PenaltyParameters penalty = parameters.penalty;
  if (parameters.quiescent_penetration > 0.0) {
    // The report's choice: the whole resting weight on one vertex sinks it x h_avg at most.
    const double weight = mass.total() * std::abs(parameters.gravity.dot(parameters.wall->normal));
    penalty.stiffness = weight / (parameters.quiescent_penetration * bodies.h_avg);
  }
  contact_stiffness = penalty.stiffness > 0.0 ? penalty.stiffness : NAN;
  contact.emplace(mesh(), PenaltyContact(penalty), parameters.contact,
                  ContactFriction(parameters.contact_friction, "contact.friction"),
                  parameters.contact_law);
  if (parameters.wall)
    contact->add_law(
        make_contact_law(parameters.wall->law,
                         {.penalty = PenaltyContact(penalty),
                          .friction = ContactFriction(parameters.wall->friction, "wall.friction"),
                          .point = parameters.wall->point,
                          .normal = parameters.wall->normal}));
  if (parameters.contact || parameters.wall) run->set_contact(*contact);
  add_boundaries(parameters, loading, mesh(), *run);
  if (parameters.bulk_viscosity.active()) {
    bulk.emplace(mesh(), parameters.bulk_viscosity, parameters.density, wave_speeds());
    bulk->set_step_ratio(bulk_step_ratio);
    bulk->set_current_configuration(parameters.corotational);
    run->set_bulk_viscosity(*bulk);
  }
  if (cracks)
    cracks->attach(*run, integrator, variation, parameters.contact ? &*contact : nullptr, 1,
                   coupling ? &*coupling : nullptr);
  run->initialize(Eigen::VectorXd::Zero(run->dofs().num_dofs()),
                  initial_velocity(parameters, loading, bodies, *run));
}

void ExplicitSimulation::step() {
  if (cracks)
    cracks->step();
  else
    run->step();
}

double ExplicitSimulation::energy_growth() const {
  const StepRecord& r = run->record();
  return (r.kinetic + r.elastic) / r.input_energy();
}

bool ExplicitSimulation::unstable() const {
  const StepRecord& r = run->record();
  const double energy = r.kinetic + r.elastic;
  return !std::isfinite(energy) || energy > kEnergyBlowUp * r.input_energy();
}

void ExplicitSimulation::archive(StateArchive& a) {
  double step = dt;
  a.value("simulation.dt", step);
  if (step != dt)
    throw CheckpointError("state: step " + fmt(step) + " s, expected " + fmt(dt) + " s");
  run->archive(a);
  if (contact) contact->archive(a);
  if (cracks) cracks->archive(a);
  if (coupling) coupling->archive(a);
  if (bulk) bulk->archive(a);
}

}  // namespace vorodg
