#pragma once
// Fragments of a cracked mesh (report section 7): the connected components of the cells, two
// cells sharing an interior edge being connected iff that edge is not cracked (union-find over
// the cells). Fragments are numbered in order of their smallest cell.
//
// Per fragment: the cell count, the mass, the centre of mass and, from node velocities, the
// velocity (momentum / mass). Masses come either from the lumped pair masses (the sum over the
// fragment's (cell, vertex) pairs, the masses the integrator moves) or from density x cell
// area. With lumped masses the centre is sum m_{c,k} X_k / m over the pairs: row-sum lumped RK
// masses reproduce first moments exactly (sum_k psi_k(x) X_k = x and the rule integrates linear
// fields), so it is the fragment's geometric centroid to round-off (tested). The velocity is
// sum m_{c,k} v(node(c, k)) / m: the momentum of the pairs, whatever the DOF map.
//
// Total mass. total_mass() is accumulated over all pairs in pair order (over all cells in cell
// order for areas): bit-for-bit LumpedMass::total(). Each fragment's mass is accumulated over
// its own pairs in the same order, so with one fragment the two agree exactly; with several,
// their sum (a different order) agrees to round-off. Mass fractions are divided by
// total_mass().
#include <Eigen/Core>
#include <vector>

#include "core/dofs/SplitDofMap.hpp"
#include "fracture/CrackState.hpp"

namespace vorodg {

class Fragments {
 public:
  /// Masses from the lumped mass of every (cell, vertex) pair of the crack state's mesh, in its
  /// pair order (LumpedMass::pair_masses(); must outlive this object).
  Fragments(const CrackState& cracks, const std::vector<double>& pair_masses);
  /// Masses as density x cell area (no velocities). Throws InputError unless density > 0.
  Fragments(const CrackState& cracks, double density);

  int num_fragments() const { return num_fragments_; }
  /// The fragment of cell c.
  int fragment(int c) const { return fragment_[c]; }
  const std::vector<int>& cell_fragments() const { return fragment_; }
  int num_cells(int f) const { return cells_[f]; }
  double mass(int f) const { return mass_[f]; }
  const Eigen::VectorXd& masses() const { return mass_; }
  /// Centres of mass in the reference configuration, one column per fragment.
  const Eigen::Matrix2Xd& centres() const { return centre_; }
  double total_mass() const { return total_; }

  /// Per fragment (columns), momentum / mass from node velocities `v` (2 per node of `dofs`,
  /// x then y) of a map of the same mesh. Needs lumped masses: throws InputError otherwise, or
  /// if `v` does not have dofs.num_dofs() entries.
  Eigen::Matrix2Xd velocities(const SplitDofMap& dofs, const Eigen::VectorXd& v) const;

  /// Fragment masses / total mass, ascending.
  Eigen::VectorXd sorted_mass_fractions() const;
  double largest_mass_fraction() const;
  /// The empirical CDF of the mass fractions: `fractions` ascending and `cumulative(i) =
  /// (i + 1) / n`, the fraction of fragments whose mass fraction is <= fractions(i) (for tied
  /// values the last of them carries the step's full height).
  struct Cdf {
    Eigen::VectorXd fractions;
    Eigen::VectorXd cumulative;
  };
  Cdf mass_fraction_cdf() const;

 private:
  void label_cells(const CrackState& cracks);
  void accumulate_lumped();
  double pair_mass(int c, int k) const;
  void accumulate_areas(double density);

  const PolygonMesh* mesh_;
  const std::vector<double>* lumped_ = nullptr;  // per pair; null: masses from areas
  std::vector<int> fragment_;
  int num_fragments_ = 0;
  std::vector<int> cells_;
  Eigen::VectorXd mass_;
  Eigen::Matrix2Xd centre_;
  double total_ = 0.0;
};

}  // namespace vorodg
