#pragma once
// Activation of coupled interfaces by the crack criterion (the report's second approach, after
// Radovitzky et al., CMAME 2011): while intact, an interface is held by the interior-penalty
// coupling (InterfaceCoupling); after each step the Mohr-Coulomb criterion is evaluated on the
// consistent interface traction, the flux {sigma}_w n - eps [u] the coupling puts across it
// (at each of its two Gauss points, in the face frame: normal out of cell 1, tension positive;
// tangent v0 -> v1); the edge activates when either point fails.
// An interface that fails leaves the coupling for a cohesive face that continues with the law
// from the traction each of its points carried (CohesiveForces::add_edge with Carried), so the
// traction does not jump and nothing is released where the carried traction is within the
// law's strength.
//
// Energy. The coupling's energy 1/2 u.K_F u of the interface leaves the elastic energy, and the
// law starts with the energy stored at its starting points: their difference is the work at
// activation (activation_work()), the energy the switch creates (> 0) or removes (< 0). It is
// not zero in general: the coupling's energy on one interface is a quadratic form of both
// cells' DOFs, not a spring's, and only the sum over the body is an energy.
//
// Interfaces are checked in order, their tractions computed into their own slots in parallel,
// so the list of activated interfaces does not depend on the thread count.
#include <Eigen/Core>
#include <vector>

#include "core/mesh/PolygonMesh.hpp"
#include "dynamics/CohesiveForces.hpp"
#include "dynamics/InterfaceCoupling.hpp"
#include "fracture/MohrCoulomb.hpp"

namespace vorodg {

class StateArchive;

class InterfaceActivation {
 public:
  /// `eligible[e]` per mesh edge: the edges that may crack (must be interfaces of `coupling`;
  /// InputError names the first that is not). `edge_strength` per edge scales the criterion's
  /// cohesion and cutoff (empty: uniform). `mesh` and `coupling` must outlive this object.
  InterfaceActivation(const PolygonMesh& mesh, InterfaceCoupling& coupling,
                      const MohrCoulomb& criterion, const std::vector<char>& eligible,
                      std::vector<double> edge_strength = {});

  struct Failure {
    int edge;
    int interface;
    Eigen::Vector2d traction;  // (normal, shear) at the more loaded Gauss point, at the check
  };
  /// The eligible, still coupled interfaces whose criterion utilization is at least 1, by edge.
  std::vector<Failure> failing(const Eigen::VectorXd& u, int threads) const;
  /// The same at the coupling's last force evaluation (InterfaceCoupling::last_traction): after
  /// a step of the run, its current displacements, without evaluating the fluxes again.
  std::vector<Failure> failing(int threads) const;
  /// The consistent traction of interface i at its two Gauss points, (normal, shear).
  std::array<Eigen::Vector2d, 2> face_tractions(int i, const Eigen::VectorXd& u) const;
  /// Each failure's interface leaves the coupling and its edge becomes a cohesive face carrying
  /// what the interface carried (not yet bound: the caller rebinds and refreshes the forces).
  void activate(const std::vector<Failure>& failures, const Eigen::VectorXd& u,
                CohesiveForces& cohesive);
  /// Sum over activations of the law's starting energy less the coupling energy removed.
  double activation_work() const { return activation_work_; }
  /// Interfaces activated so far.
  int activated() const { return activated_; }

  /// Saves or loads its accounts (a checkpoint).
  void archive(StateArchive& a);

 private:
  const PolygonMesh& mesh_;
  InterfaceCoupling& coupling_;
  MohrCoulomb criterion_;
  std::vector<int> candidates_;  // the eligible interfaces, by edge
  std::vector<double> edge_strength_;
  std::vector<Eigen::Vector2d> normal_, tangent_;  // per candidate
  double activation_work_ = 0.0;
  /// The failures with the interface tractions `tractions(i)` (global, at the Gauss points).
  template <class Tractions>
  std::vector<Failure> check(const Tractions& tractions, int threads) const;
  int activated_ = 0;
};

}  // namespace vorodg
