#include "dynamics/InterfaceActivation.hpp"

#include <algorithm>
#include <string>

#include "core/io/StateArchive.hpp"
#include "core/util/Errors.hpp"
#include "fracture/FaceInsertion.hpp"

namespace vorodg {

InterfaceActivation::InterfaceActivation(const PolygonMesh& mesh, InterfaceCoupling& coupling,
                                         const MohrCoulomb& criterion,
                                         const std::vector<char>& eligible,
                                         std::vector<double> edge_strength)
    : mesh_(mesh),
      coupling_(coupling),
      criterion_(criterion),
      edge_strength_(std::move(edge_strength)) {
  if (static_cast<int>(eligible.size()) != mesh.num_edges())
    throw InputError("interface activation: " + std::to_string(eligible.size()) +
                     " eligibility flags, expected one per edge (" +
                     std::to_string(mesh.num_edges()) + ")");
  for (int e = 0; e < mesh.num_edges(); ++e) {
    if (!eligible[e] || mesh.edge(e).cell1 < 0) continue;
    const int i = coupling.interface_of_edge(e);
    if (i < 0)
      throw InputError("interface activation: edge " + std::to_string(e) +
                       " may crack but is not a coupled interface");
    candidates_.push_back(i);
    const Interface& f = coupling.space().interfaces()[i];
    normal_.push_back(f.normal);
    tangent_.push_back((f.b - f.a) / f.length);
  }
}

std::array<Eigen::Vector2d, 2> InterfaceActivation::face_tractions(int i,
                                                                   const Eigen::VectorXd& u) const {
  const Interface& f = coupling_.space().interfaces()[i];
  const Eigen::Vector2d t = (f.b - f.a) / f.length;
  const auto global = coupling_.traction(i, u);
  return {Eigen::Vector2d(global[0].dot(f.normal), global[0].dot(t)),
          Eigen::Vector2d(global[1].dot(f.normal), global[1].dot(t))};
}

std::vector<InterfaceActivation::Failure> InterfaceActivation::failing(const Eigen::VectorXd& u,
                                                                       int threads) const {
  return check([&](int i) { return coupling_.traction(i, u); }, threads);
}

std::vector<InterfaceActivation::Failure> InterfaceActivation::failing(int threads) const {
  return check([&](int i) { return coupling_.last_traction(i); }, threads);
}

template <class Tractions>
std::vector<InterfaceActivation::Failure> InterfaceActivation::check(const Tractions& tractions,
                                                                     int threads) const {
  const int n = static_cast<int>(candidates_.size());
  std::vector<double> utilization(n, 0.0);
  std::vector<Eigen::Vector2d> mean(n, Eigen::Vector2d::Zero());
#pragma omp parallel for schedule(static, 256) num_threads(std::max(threads, 1))
  for (int k = 0; k < n; ++k) {
    const int i = candidates_[k];
    if (!coupling_.active(i)) continue;
    // Each Gauss point is checked, as the quasi-static solver checks its points: the flux is
    // linear along the edge, and at a notch tip its peak is at one end. The edge activates as a
    // whole when either point fails; `traction` reports the more loaded point's.
    const std::array<Eigen::Vector2d, 2> global = tractions(i);
    const int e = coupling_.space().interfaces()[i].edge;
    const double factor = edge_strength_.empty() ? 1.0 : edge_strength_[e];
    for (const Eigen::Vector2d& g : global) {
      const Eigen::Vector2d t(g.dot(normal_[k]), g.dot(tangent_[k]));
      const double u = face_utilization(criterion_, t, factor);
      if (u >= utilization[k]) utilization[k] = u, mean[k] = t;
    }
  }
  std::vector<Failure> out;
  for (int k = 0; k < n; ++k)
    if (utilization[k] >= 1.0)
      out.push_back({coupling_.space().interfaces()[candidates_[k]].edge, candidates_[k], mean[k]});
  return out;
}

void InterfaceActivation::activate(const std::vector<Failure>& failures, const Eigen::VectorXd& u,
                                   CohesiveForces& cohesive) {
  for (const Failure& f : failures) {
    CohesiveForces::Carried carried;
    carried.traction = face_tractions(f.interface, u);
    carried.jump = coupling_.opening(f.interface, u);
    const double before = cohesive.continuation_energy();
    const double coupled = coupling_.energy(f.interface, u);
    coupling_.deactivate(f.interface);
    cohesive.add_edge(f.edge, carried);
    activation_work_ += cohesive.continuation_energy() - before - coupled;
    ++activated_;
  }
}

void InterfaceActivation::archive(StateArchive& a) {
  a.value("activation.work", activation_work_);
  a.value("activation.activated", activated_);
}

}  // namespace vorodg
