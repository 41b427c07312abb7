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
// The blocks are built once (each is (2 n_1 + 2 n_2)^2 doubles); a force evaluation is one dense
// mat-vec per interface, in interface order, so it is the same for any thread count.
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "core/dofs/SplitDofMap.hpp"
#include "core/element/ElasticityIntegrator.hpp"
#include "core/element/ElementTable.hpp"
#include "interfaces/DgSpace.hpp"
#include "interfaces/InterfaceOperators.hpp"
#include "interfaces/InterfacePenalty.hpp"

namespace vorodg {

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

  /// Adds -K u (the coupling's force) to f (node DOFs of the map) and returns the coupling's
  /// energy 1/2 u.K u. Throws InputError if u or f has the wrong size.
  double add_forces(const Eigen::VectorXd& u, Eigen::VectorXd& f) const;
  /// A bound of the largest eigenvalue of M^-1 K_I (K_I all the interface blocks, M the node
  /// masses): Gershgorin on M^-1/2 K_I M^-1/2. Added to the cells' bound it bounds the whole
  /// system's, since lambda_max(A + B) <= lambda_max(A) + lambda_max(B).
  double eigenvalue_bound(const Eigen::VectorXd& node_masses) const;

 private:
  std::unique_ptr<DgSpace> space_;
  std::unique_ptr<InterfaceOperators> ops_;
  std::unique_ptr<InterfacePenalty> penalty_;
  std::vector<Eigen::MatrixXd> blocks_;
  std::vector<std::vector<int>> dofs_;
  int num_dofs_ = 0;
  Eigen::Index largest_block_ = 0;
};

}  // namespace vorodg
