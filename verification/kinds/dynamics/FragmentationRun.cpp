#include "verification/kinds/dynamics/FragmentationRun.hpp"

#include <cmath>
#include <memory>
#include <sstream>

#include "core/io/AtomicFile.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "dynamics/CorotationalFrames.hpp"
#include "fracture/Fragments.hpp"
#include "verification/kinds/dynamics/CrackLocations.hpp"
#include "verification/model/SettingsSchema.hpp"
#include "verification/report/ConvergenceTable.hpp"

namespace fs = std::filesystem;

namespace vorodg {
namespace {

CohesiveParameters with_stiffness(const DynamicsScene& scene, double h_avg) {
  CohesiveParameters p = scene.cohesive;
  p.initial_stiffness = scene.stiffness_factor * scene.E / h_avg;
  return p;
}

CohesiveLaw make_law(const DynamicsScene& scene, double h_avg) {
  try {
    return CohesiveLaw(with_stiffness(scene, h_avg));
  } catch (const InputError& e) {
    throw InputError("cohesive.initial_stiffness " + fmt(scene.stiffness_factor) +
                     " x E / h_avg (" + fmt(h_avg) + " m): " + e.what());
  }
}

/// The mass in fragments of a single cell over the total: the sand.
double single_cell_mass_fraction(const Fragments& pieces) {
  double sand = 0.0;
  for (int f = 0; f < pieces.num_fragments(); ++f)
    if (pieces.num_cells(f) == 1) sand += pieces.mass(f);
  return sand / pieces.total_mass();
}

}  // namespace

double FragmentationRun::main_body_rotation(const Fragments& pieces, const LumpedMass& mass) const {
  const Eigen::VectorXd& masses = pieces.masses();
  Eigen::Index largest = 0;
  masses.maxCoeff(&largest);
  const CorotationalFrames frames(mesh_);
  Eigen::Matrix2d F = Eigen::Matrix2d::Zero();  // mass-weighted sum over the fragment's cells
  for (int c = 0; c < mesh_.num_cells(); ++c) {
    if (pieces.fragment(c) != largest) continue;
    double cell_mass = 0.0;
    for (double m : mass.cell(c)) cell_mass += m;
    F += cell_mass * (Eigen::Matrix2d::Identity() +
                      frames.displacement_gradient(c, run_->dofs(), run_->displacement()));
  }
  return std::atan2(F(1, 0) - F(0, 1), F(0, 0) + F(1, 1));
}

FragmentationRun::FragmentationRun(const DynamicsScene& scene, const PolygonMesh& mesh,
                                   double h_avg)
    : mesh_(mesh),
      law_(make_law(scene, h_avg)),
      criterion_(scene.criterion),
      sites_(scene.problem->crack_sites(mesh)),
      eligible_(sites_.eligible.empty() ? std::vector<char>(mesh.num_edges(), 1) : sites_.eligible),
      friction_(scene.face_friction),
      closure_{scene.closure_fraction, {}},
      turning_frames_(scene.corotational && scene.turning_faces),
      body_(scene.bodies[0].domain) {
  if (scene.wall) impact_ = scene.wall->point;
}

void FragmentationRun::close_as_interfaces(const InterfaceCoupling& coupling) {
  const double k0 = law_.parameters().initial_stiffness;
  closure_.per_edge.assign(mesh_.num_edges(), closure_.fraction * k0);  // edges never cracked
  for (int e = 0; e < mesh_.num_edges(); ++e)
    if (const int i = coupling.interface_of_edge(e); i >= 0)
      closure_.per_edge[e] = coupling.penalty(i);
}

std::vector<char> FragmentationRun::spring_edges() const {
  std::vector<char> springs = eligible_;  // and the faces there from t = 0
  for (int e : sites_.pre_inserted) springs[e] = 1;
  return springs;
}

double FragmentationRun::eigenvalue_bound(const StableTimeStep& cells, const LumpedMass& mass,
                                          double coupling_eigenvalue) const {
  // lambda_max of a sum is at most the sum of the parts' (an edge is coupled or cohesive, never
  // both, so this is conservative with interfaces coupled from the start).
  return cells.max_eigenvalue() + coupling_eigenvalue +
         CohesiveForces::eigenvalue_bound(mesh_, mass, law_, spring_edges(), friction_, closure_);
}

GlobalTimeStep FragmentationRun::estimated_step(InternalForce& force, const LumpedMass& mass,
                                                double bound) const {
  const std::vector<char> springs = spring_edges();
  std::vector<char> connected(mesh_.num_edges());
  for (int e = 0; e < mesh_.num_edges(); ++e) connected[e] = !springs[e];
  const SplitDofMap split(mesh_, connected);
  const Eigen::SparseMatrix<double> K_s =
      CohesiveForces::spring_stiffness(mesh_, split, law_, springs, friction_, closure_);
  return GlobalTimeStep(
      [&](const Eigen::VectorXd& x, Eigen::VectorXd& Kx) {
        force.compute(split, x, Kx, 1);
        Kx += K_s * x;
      },
      mass.node_masses(split), bound);
}

void FragmentationRun::attach(CentralDifference& run, const ElasticityIntegrator& integrator,
                              const MaterialVariation& variation, ContactForces* contact,
                              int threads, InterfaceCoupling* coupling) {
  run_ = &run;
  contact_ = contact;
  cohesive_ = std::make_unique<CohesiveForces>(mesh_, law_);
  cohesive_->set_edge_strength(variation.edge_strength(mesh_));
  cohesive_->set_friction(friction_);
  cohesive_->set_closure(closure_);
  cohesive_->set_turning_frames(turning_frames_);
  // The faces there from t = 0, exposed to contact like every crack; DynamicFracture takes them
  // as cracked, and the run's DOF map is split along them from the start (DynamicsModel).
  for (int e : sites_.pre_inserted) cohesive_->add_edge(e);
  if (contact)
    for (const std::vector<int>* edges : {&sites_.pre_inserted, &sites_.free})
      for (int e : *edges) contact->surface().expose(e);
  insertion_ = std::make_unique<CrackInsertion>(mesh_, integrator, criterion_, eligible_, threads);
  insertion_->vary(variation);
  insertion_->turn_with(run.force().frames());
  fracture_ = std::make_unique<DynamicFracture>(mesh_, run, *cohesive_, *insertion_, contact);
  fracture_->cut(sites_.free);
  if (coupling) {
    activation_ = std::make_unique<InterfaceActivation>(mesh_, *coupling, criterion_, eligible_,
                                                        variation.edge_strength(mesh_));
    fracture_->set_activation(*activation_);
  }
}

void FragmentationRun::step() {
  fracture_->step(1);
}

void FragmentationRun::check_balance(const StepRecord& r) {
  // The leapfrog kinetic energy, which the works' trapezoids balance: the whole-step one differs
  // by dt^2/8 a.M a, which at the first steps of a prescribed velocity from rest is most of the
  // (tiny) input.
  if (r.step == 0) start_ = r.kinetic_leapfrog + r.elastic;
  // Contact by its springs' closed form too (the energy they store now), beside what its
  // velocity penalty (its own booked work) and its friction (the slip work) have taken: the
  // whole contact's booked work would hide energy that a spring switching on at depth creates.
  const double contact = contact_ ? contact_->report().potential +
                                        contact_->velocity_penalty_dissipated() +
                                        contact_->friction_dissipated()
                                  : 0.0;
  const double held = r.kinetic_leapfrog + r.elastic + cohesive_->dissipated_energy() +
                      cohesive_->stored_energy() + r.damping_dissipation +
                      r.bulk_viscosity_dissipation + contact +
                      cohesive_->friction_dissipated_energy();
  // Coupled interfaces: the law starts with energy the coupling held (InterfaceActivation).
  // Splits: a split copies u and v, so it changes no cell's energy and not 1/2 v.M v, but the
  // restart's new accelerations move K* by dt^2/8 of a.M a (the integrator's remap energy): a
  // face inserted at zero traction into a loaded body changes its nodes' accelerations most.
  const double put_in = start_ + r.external_work + r.reaction_work + r.remap_energy +
                        (activation_ ? activation_->activation_work() : 0.0);
  input_energy_ = r.input_energy();
  const double balance = std::abs(held - put_in) / std::max(input_energy_, 1e-300);
  worst_balance_ = std::max(worst_balance_, balance);
  if (std::isnan(breach_time_) && balance > kLawBalanceLimit) breach_time_ = r.time;
}

std::vector<VtuField> FragmentationRun::cell_fields(const LumpedMass& mass) const {
  const Fragments pieces(fracture_->broken_state(), mass.pair_masses());
  VtuField fragment{"fragment", 1, {}}, cracked{"cracked_edges", 1, {}};
  for (int c = 0; c < mesh_.num_cells(); ++c) {
    fragment.values.push_back(pieces.fragment(c));
    int n = 0;
    for (int e : mesh_.cell_edges(c)) n += fracture_->cracked()[e];
    cracked.values.push_back(n);
  }
  return {fragment, cracked};
}

void FragmentationRun::finish(const fs::path& out, const std::string& id, const LumpedMass& mass,
                              DynamicsMeasures& m) const {
  const Fragments pieces(fracture_->broken_state(), mass.pair_masses());
  m.fragments = pieces.num_fragments();
  m.max_fragment_mass_fraction = pieces.largest_mass_fraction();
  m.single_cell_mass_fraction = single_cell_mass_fraction(pieces);
  m.main_body_rotation = main_body_rotation(pieces, mass);
  m.dissipated_energy = cohesive_->dissipated_energy();
  m.cracked_edges = static_cast<double>(cohesive_->edges().size());
  m.broken_edges = cohesive_->num_broken();
  m.face_friction_dissipated = cohesive_->friction_dissipated_energy();
  if (impact_) {
    std::vector<int> broken;
    for (int e : cohesive_->edges())
      if (cohesive_->broken(e)) broken.push_back(e);
    const CrackLocations where = crack_locations(mesh_, broken, body_, *impact_);
    m.broken_near_impact = where.near_impact;
    m.broken_mid_length = where.mid_length;
    m.broken_elsewhere = where.elsewhere;
  }
  m.released_edges = static_cast<double>(cohesive_->released_edges().size());
  if (activation_) {
    m.activated_interfaces = activation_->activated();
    m.activation_work = activation_->activation_work() / std::max(input_energy_, 1e-300);
  }
  m.check_seconds = fracture_->times().check;
  m.rebuild_seconds = fracture_->times().rebuild;
  m.law_balance_error = worst_balance_;
  m.law_balance_breach_time = breach_time_;
  const Eigen::Matrix2Xd v = pieces.velocities(run_->dofs(), run_->velocity());
  ConvergenceTable f;  // fragments/<run>.csv: what each fragment is and where it goes
  for (const char* column : {"fragment", "mass", "cells", "x", "y", "vx", "vy"})
    f.declare_column(column,
                     std::string_view(column) == "fragment" || std::string_view(column) == "cells"
                         ? integer_style()
                         : shortest_csv_style());
  for (int i = 0; i < pieces.num_fragments(); ++i) {
    f.start_row();
    for (const auto& [column, value] : {std::pair{"fragment", double(i)},
                                        {"mass", pieces.mass(i)},
                                        {"cells", double(pieces.num_cells(i))},
                                        {"x", pieces.centres()(0, i)},
                                        {"y", pieces.centres()(1, i)},
                                        {"vx", v(0, i)},
                                        {"vy", v(1, i)}})
      f.add_value(column, value);
  }
  fs::create_directories(out / "fragments");
  write_file_atomically(out / "fragments" / (id + ".csv"), csv_text(f));
  ConvergenceTable c;  // cracks/<run>.csv: the step at which each edge cracked
  for (const char* column : {"step", "edge"}) c.declare_column(column, integer_style());
  for (const CrackEvent& e : fracture_->events()) {
    c.start_row();
    c.add_value("step", static_cast<double>(e.step));
    c.add_value("edge", e.edge);
  }
  fs::create_directories(out / "cracks");
  write_file_atomically(out / "cracks" / (id + ".csv"), csv_text(c));
}

}  // namespace vorodg
