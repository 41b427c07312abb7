#pragma once
// Interfaces that are part of the discrete equations from the start (the report's second
// approach, after Radovitzky et al., CMAME 2011): on a DOF map that splits the crack-capable
// edges at t = 0, each split edge is held together, while intact, by the same symmetric
// interior-penalty terms the quasi-static DG solver uses (interfaces/: the coercive penalty of
// the cells' trace constants, fan tractions, plain average):
//     K_F = eps_F int_F [u].[v]  -  int_F {sigma(u)} n.[v]  -  int_F {sigma(v)} n.[u],
// written for the explicit step as the force f = -K_F u on the edge's two cells. The forces are
// linear in u and derive from the coupling's energy 1/2 u.K_F u, which is not positive on one
// interface but is, with the cells' energy, on the whole (the penalty is coercive), so it is
// booked with the elastic energy.
//
// The blocks are built once (each is (2 n_1 + 2 n_2)^2 doubles), for the step's bound and for
// tests; a force evaluation uses their factors instead, the flux and the jump at the two Gauss
// points (4 x m each): four mat-vecs of 4 rows per interface in place of one m x m, in interface
// order, so it is the same for any thread count.
#include <Eigen/Core>
#include <array>
#include <memory>
#include <vector>

#include "core/dofs/SplitDofMap.hpp"
#include "core/element/ElasticityIntegrator.hpp"
#include "core/element/ElementTable.hpp"
#include "interfaces/DgSpace.hpp"
#include "interfaces/InterfaceOperators.hpp"
#include "interfaces/InterfacePenalty.hpp"

namespace vorodg {

class StateArchive;

class InterfaceCoupling {
 public:
  /// The interfaces of `dofs` (the interior edges it splits) on the table's mesh, with the
  /// coercive penalty times `kp` (> 1/2 for coercivity; 1 is the quasi-static default). `table` and
  /// `integrator` must outlive the object (the map is copied). Throws InputError for kp <= 0.
  InterfaceCoupling(const ElementTable& table, const ElasticityIntegrator& integrator,
                    const ElasticityIntegrator::CellMatrices& cells, const SplitDofMap& dofs,
                    double kp = 1.0, int threads = 1);

  int num_interfaces() const { return static_cast<int>(blocks_.size()); }
  const DgSpace& space() const { return *space_; }
  double penalty(int i) const { return penalty_->eps(i); }
  /// Interface i's block K_F on its DOFs (space().interfaces()[i], the node DOFs of `dofs`).
  const Eigen::MatrixXd& block(int i) const { return blocks_[i]; }
  const std::vector<int>& block_dofs(int i) const { return dofs_[i]; }

  /// The interface on mesh edge e, or -1 (not split by the map).
  int interface_of_edge(int e) const { return interface_of_edge_[e]; }
  bool active(int i) const { return active_[i] != 0; }
  /// Interface i lets go of its coupling for good (it has been activated as a crack): its block
  /// no longer acts. Throws InputError if it is not active.
  void deactivate(int i);
  /// Interface i's energy 1/2 u_F.K_F u_F now.
  double energy(int i, const Eigen::VectorXd& u) const;
  /// The consistent interface traction at interface i's two Gauss points (segment rule, from
  /// v0): the flux the coupling puts across the interface, {sigma(u)}_w n - eps [u] (n out of
  /// cell 1, [u] = u_1 - u_2), in the global frame. It is what holds the two cells together;
  /// for a continuous field it is sigma n.
  std::array<Eigen::Vector2d, 2> traction(int i, const Eigen::VectorXd& u) const;
  /// traction(i, u) at the u of the last add_forces (which computes it on the way): what the
  /// check after a step reads, at no extra cost.
  std::array<Eigen::Vector2d, 2> last_traction(int i) const;
  /// The jump u_2 - u_1 (the cohesive faces' opening) at interface i's two Gauss points.
  std::array<Eigen::Vector2d, 2> opening(int i, const Eigen::VectorXd& u) const;

  /// Adds -K u (the coupling's force) to f (node DOFs of the map) and returns the coupling's
  /// energy 1/2 u.K u, over the active interfaces. Throws InputError if u or f has the wrong size.
  double add_forces(const Eigen::VectorXd& u, Eigen::VectorXd& f) const;
  /// A bound of the largest eigenvalue of M^-1 K_I (K_I the active interfaces' blocks, M the
  /// node masses; an interface deactivated later only lowers it): Gershgorin on M^-1/2 K_I M^-1/2.
  /// Added to the cells' bound it bounds the whole system's, since lambda_max(A + B) <=
  /// lambda_max(A) + lambda_max(B).
  double eigenvalue_bound(const Eigen::VectorXd& node_masses) const;

  /// Saves or loads which interfaces still couple and their last fluxes (a checkpoint).
  void archive(StateArchive& a);

 private:
  std::unique_ptr<DgSpace> space_;
  std::unique_ptr<InterfaceOperators> ops_;
  std::unique_ptr<InterfacePenalty> penalty_;
  std::vector<Eigen::MatrixXd> blocks_;
  std::vector<std::vector<int>> dofs_;
  // Per interface, the flux (4 rows: x, y at Gauss point 0, then at point 1) on its DOFs, and
  // the jump [u] (the same rows) on its nonzero columns only: the edge's end vertices of each
  // cell (8 of m); per interface whether it still couples; per edge its interface.
  std::vector<Eigen::Matrix<double, 4, Eigen::Dynamic>> flux_;
  std::vector<Eigen::Matrix<double, 4, 8>> jump_compact_;
  std::vector<std::array<int, 8>> jump_columns_;
  std::vector<char> active_;
  mutable std::vector<Eigen::Vector4d> last_flux_;  // per interface, at the last add_forces
  std::vector<int> interface_of_edge_;
  /// Interface i's DOFs relative to its first vertex's (what K_F, the flux and the jump see).
  Eigen::VectorXd local(int i, const Eigen::VectorXd& u) const;
  int num_dofs_ = 0;
  Eigen::Index largest_block_ = 0;
};

}  // namespace vorodg
