#pragma once
// Row-sum lumped masses of the RK polygon element (report sections 4 and 6), kept per (cell,
// vertex) pair rather than per node so that any DOF map can be given its node masses.
//
// What is computed. Per unit thickness, pair (c, k) gets
//     m_{c,k} = rho sum_q w_q psi_k(x_q),
// the row sum of the cell's consistent mass matrix M_kl = rho sum_q w_q psi_k psi_l: the shape
// functions sum to one at every quadrature point (partition of unity, kept to round-off by the
// element layer), so sum_l psi_l(x_q) = 1 and the row sum is the quadrature of psi_k alone. The
// pair masses of a cell therefore add up to rho times the sum of its quadrature weights, which
// is the cell's area: the total mass is rho times the domain area (tested to 1e-12).
//
// Why per pair. A node's mass is the sum of the masses of the pairs it holds, rebuilt by
// node_masses() for any SplitDofMap. When a crack splits a node, each new node keeps exactly its
// own pairs' mass; copying the velocity to both halves then keeps the linear momentum (and the
// kinetic energy) of the split node unchanged.
//
// Positivity. RK shape functions may dip below zero somewhere in a cell, but their integral
// should not: a pair mass <= 0 would make the explicit update meaningless (division by a
// non-positive mass, no stable time step). It is refused with a NumericalError naming the cell
// and the vertex, rather than clipped, because clipping would silently change the total mass.
#include <Eigen/Core>
#include <span>
#include <vector>

#include "core/dofs/SplitDofMap.hpp"
#include "core/element/ElementTable.hpp"

namespace vorodg {

class LumpedMass {
 public:
  /// Needs the table's point values (build it before ElementTable::release_point_values).
  /// Throws InputError unless density > 0, NumericalError naming the cell and vertex if a pair
  /// mass is not positive.
  LumpedMass(const ElementTable& table, double density);

  double density() const { return density_; }
  int num_pairs() const { return static_cast<int>(pair_.size()); }
  /// Mass of cell c's vertex k (k in the cell's loop order).
  double pair_mass(int c, int k) const { return pair_[offsets_[c] + k]; }
  /// The masses of cell c's pairs, in loop order.
  std::span<const double> cell(int c) const {
    return {pair_.data() + offsets_[c], pair_.data() + offsets_[c + 1]};
  }
  /// Every pair mass, CSR like the mesh's cell loops.
  const std::vector<double>& pair_masses() const { return pair_; }
  /// Sum of the pair masses (in pair order): rho times the domain area.
  double total() const { return total_; }
  /// Per node of `dofs` (a map of the same mesh), the sum of its pairs' masses, added in pair
  /// order so the result does not depend on how the map was built or on threads.
  Eigen::VectorXd node_masses(const SplitDofMap& dofs) const;
  /// The same for node i alone.
  double node_mass(const SplitDofMap& dofs, int i) const;

 private:
  std::vector<int> offsets_;
  std::vector<double> pair_;
  double density_ = 0.0;
  double total_ = 0.0;
};

}  // namespace vorodg
