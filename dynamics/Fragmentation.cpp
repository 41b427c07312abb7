#include "dynamics/Fragmentation.hpp"

#include <cmath>
#include <memory>
#include <utility>

#include "core/io/StateArchive.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"
#include "dynamics/CorotationalFrames.hpp"

namespace vorodg {
namespace {

CohesiveParameters with_stiffness(const ExplicitParameters& p, double h_avg) {
  CohesiveParameters law = p.cohesive;
  law.initial_stiffness = p.stiffness_factor * p.E / h_avg;
  return law;
}

CohesiveLaw make_law(const ExplicitParameters& p, double h_avg) {
  try {
    return CohesiveLaw(with_stiffness(p, h_avg));
  } catch (const InputError& e) {
    throw InputError("cohesive.initial_stiffness " + fmt(p.stiffness_factor) + " x E / h_avg (" +
                     fmt(h_avg) + " m): " + e.what());
  }
}

}  // namespace

double Fragmentation::main_body_rotation(const Fragments& pieces, const LumpedMass& mass) const {
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

Fragmentation::Fragmentation(const ExplicitParameters& p, const PolygonMesh& mesh, double h_avg,
                             CrackSites sites)
    : mesh_(mesh),
      law_(make_law(p, h_avg)),
      criterion_(p.criterion),
      sites_(std::move(sites)),
      eligible_(sites_.eligible.empty() ? std::vector<char>(mesh.num_edges(), 1) : sites_.eligible),
      friction_(p.face_friction),
      closure_{p.closure_fraction, {}},
      turning_frames_(p.corotational && p.turning_faces) {}

void Fragmentation::close_as_interfaces(const InterfaceCoupling& coupling) {
  const double k0 = law_.parameters().initial_stiffness;
  closure_.per_edge.assign(mesh_.num_edges(), closure_.fraction * k0);  // edges never cracked
  for (int e = 0; e < mesh_.num_edges(); ++e)
    if (const int i = coupling.interface_of_edge(e); i >= 0)
      closure_.per_edge[e] = coupling.penalty(i);
}

std::vector<char> Fragmentation::spring_edges() const {
  std::vector<char> springs = eligible_;  // and the faces there from t = 0
  for (int e : sites_.pre_inserted) springs[e] = 1;
  return springs;
}

double Fragmentation::eigenvalue_bound(const StableTimeStep& cells, const LumpedMass& mass,
                                       double coupling_eigenvalue) const {
  // lambda_max of a sum is at most the sum of the parts' (an edge is coupled or cohesive, never
  // both, so this is conservative with interfaces coupled from the start).
  return cells.max_eigenvalue() + coupling_eigenvalue +
         CohesiveForces::eigenvalue_bound(mesh_, mass, law_, spring_edges(), friction_, closure_);
}

GlobalTimeStep Fragmentation::estimated_step(InternalForce& force, const LumpedMass& mass,
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

void Fragmentation::attach(CentralDifference& run, const ElasticityIntegrator& integrator,
                           const MaterialVariation& variation, ContactForces* contact, int threads,
                           InterfaceCoupling* coupling) {
  run_ = &run;
  contact_ = contact;
  cohesive_ = std::make_unique<CohesiveForces>(mesh_, law_);
  cohesive_->set_edge_strength(variation.edge_strength(mesh_));
  cohesive_->set_friction(friction_);
  cohesive_->set_closure(closure_);
  cohesive_->set_turning_frames(turning_frames_);
  // The faces there from t = 0, exposed to contact like every crack; DynamicFracture takes them
  // as cracked, and the run's DOF map is split along them from the start (ExplicitSimulation).
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

void Fragmentation::step() {
  fracture_->step(1);
}

void Fragmentation::check_balance(const StepRecord& r) {
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

std::vector<VtuField> Fragmentation::cell_fields(const LumpedMass& mass) const {
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

void Fragmentation::archive(StateArchive& a) {
  a.value("fragmentation.start", start_);
  a.value("fragmentation.worst_balance", worst_balance_);
  a.value("fragmentation.input_energy", input_energy_);
  a.value("fragmentation.breach_time", breach_time_);
  cohesive_->archive(a);
  if (fracture_) fracture_->archive(a);
  if (activation_) activation_->archive(a);
}

}  // namespace vorodg
