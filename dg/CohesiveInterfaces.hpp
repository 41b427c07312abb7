#pragma once
// The interface terms of cohesive fracture in the DG form. Each interface carries two Gauss
// points, and each point a state (docs/fracture.md "Interface states"):
//   intact:   coupled as in dg-sipg: w (eps [u].[v] - {sigma(u)}n.[v] - {sigma(v)}n.[u]), which
//             is consistent, so the jump vanishes wherever the exact solution is continuous;
//   cohesive: the traction of the cohesive law on the opening g = u_2 - u_1 in the face frame
//             (normal n from cell 1 to cell 2, tangent (-n_y, n_x)), tension resisting opening;
//   open:     traction-free (a notch, a fully softened crack);
// and in the two non-intact states a penalty eps <g_n>_- against overclosure (contact, which the
// cohesive law leaves alone). An intact point whose traction {sigma}n, from the two cells'
// stresses, meets the Mohr-Coulomb criterion may turn cohesive; which points are eligible is the
// cracking mode's business, not this object's.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstdint>
#include <functional>
#include <vector>

#include "fracture/CohesiveLaw.hpp"
#include "fracture/MohrCoulomb.hpp"
#include "interfaces/InterfaceOperators.hpp"
#include "interfaces/InterfacePenalty.hpp"

namespace vorodg {

enum class PointState : std::uint8_t { intact, cohesive, open };

struct InterfacePoint {
  PointState state = PointState::intact;
  CohesiveLaw::State history;  // the largest effective opening so far (cohesive, open)
  // The opening when the point turned cohesive: the weakly continuous field's jump there. The
  // law acts on the opening beyond it, so that the traction does not jump at insertion.
  Eigen::Vector2d offset = Eigen::Vector2d::Zero();
};

/// Energies per unit thickness.
struct InterfaceEnergies {
  double coupling = 0.0;      // intact points: the quadratic form of the SIPG terms
  double cohesive = 0.0;      // recoverable: unloading lines and the overclosure penalty
  double dissipated = 0.0;    // the law's dissipation, summed over the points
  double crack_length = 0.0;  // length of the faces whose points are not intact
};

class CohesiveInterfaces {
 public:
  CohesiveInterfaces(const InterfaceOperators& ops, const InterfacePenalty& penalty,
                     TractionKind kind, const CohesiveLaw& law, const MohrCoulomb& criterion);

  int num_points() const { return 2 * static_cast<int>(ops_.space().interfaces().size()); }
  /// Receives a dense block on the DOFs of interface `face` (InterfaceOperators::dofs order).
  using BlockSink = std::function<void(int face, const Eigen::MatrixXd& block)>;
  int num_faces() const { return static_cast<int>(dofs_.size()); }
  /// The SIPG matrix of every face as if all its points were intact: with the bulk, the base
  /// that add() corrects (the pattern of the tangent never changes).
  void add_intact(const BlockSink& sink) const;
  /// Adds to `force` what the non-intact points change with respect to that base: their coupling
  /// taken out, their face law put in; and, if `tangent` is given, the derivative of that, one
  /// block per face that has a non-intact point. Cohesive points advance their history in
  /// `points` (pass a trial copy while iterating).
  void add(const Eigen::VectorXd& u, std::vector<InterfacePoint>& points, Eigen::VectorXd& force,
           const BlockSink* tangent) const;
  /// Global DOFs of interface i (cell 1's, then cell 2's).
  const std::vector<int>& dofs(int i) const { return dofs_[i]; }
  /// The opening (normal, tangential) at point p: g = u_2 - u_1 in the face frame.
  Eigen::Vector2d opening(const Eigen::VectorXd& u, int p) const;
  /// The traction (normal, shear) an intact point transmits, in the face frame: the interior
  /// penalty flux {sigma}n - eps [u], the cells' stresses corrected by the penalty on the jump.
  Eigen::Vector2d flux_traction(const Eigen::VectorXd& u, int p) const;
  /// The Mohr-Coulomb utilization of that traction (>= 1: the point fails).
  double utilization(const Eigen::VectorXd& u, int p) const;
  InterfaceEnergies energies(const Eigen::VectorXd& u,
                             const std::vector<InterfacePoint>& points) const;
  const Interface& face(int p) const { return ops_.space().interfaces()[p / 2]; }
  /// Quadrature weight (length included) of point p.
  double weight(int p) const;
  /// The scene's law (the nominal strength and fracture energy: the path's scales).
  const CohesiveLaw& law() const { return law_; }
  /// The law at point p: the scene's, or its face's when the strength varies.
  const CohesiveLaw& law(int p) const {
    return face_laws_.empty() ? law_ : face_laws_[static_cast<std::size_t>(p / 2)];
  }
  /// A strength varying from edge to edge (MaterialVariation::edge_strength, one factor per mesh
  /// edge): face i's law has factor x sigma_c (G, beta and K0 unchanged), and its criterion's
  /// cohesion and cutoff scale by the factor. An empty vector restores the uniform strength.
  void set_edge_strength(const std::vector<double>& factor);

 private:
  Eigen::VectorXd local(const Eigen::VectorXd& u, int i) const;
  Eigen::Matrix2d frame(int i) const;  // rows n^T and t^T
  InterfaceOperator jump(int p) const;
  /// Point p's SIPG matrix (m x m on the face's DOFs).
  Eigen::MatrixXd intact_block(int p) const;
  /// The law plus the overclosure penalty at a non-intact point: traction and tangent in the
  /// face frame.
  void face_law(int p, const Eigen::Vector2d& g, InterfacePoint& point, Eigen::Vector2d& tau,
                Eigen::Matrix2d& C) const;
  /// The cohesive law's part of face_law, on the opening beyond the point's offset.
  void cohesive_law(const CohesiveLaw& law, double eps, const Eigen::Vector2d& g,
                    InterfacePoint& point, Eigen::Vector2d& tau, Eigen::Matrix2d& C) const;

  const InterfaceOperators& ops_;
  const InterfacePenalty& penalty_;
  const CohesiveLaw& law_;
  const MohrCoulomb& criterion_;
  std::vector<CohesiveLaw> face_laws_;       // per interface when the strength varies
  std::vector<double> face_strength_;        // per interface when the strength varies
  std::vector<std::vector<int>> dofs_;       // per interface
  std::vector<InterfaceOperator> traction_;  // per point: {sigma}_w n
};

}  // namespace vorodg
