#pragma once
// The cell-stiffness kernel CG and DG share: K_c = sum_q w_q B_q^T D B_q over the element
// table's quadrature points, with the standard strain operator or the mean-dilation (B-bar) one
// whose volumetric part is the cell mean (report section 3, Figure 8); for the virtual element,
// plus its stabilization.
// Cell DOFs are ordered (u_x, u_y) per cell vertex, in the cell's loop order.
#include <Eigen/Core>
#include <vector>

#include "core/element/ElementTable.hpp"
#include "core/element/StrainOperator.hpp"
#include "core/material/IsotropicElasticity.hpp"

namespace vorodg {

class ElasticityIntegrator {
 public:
  ElasticityIntegrator(const ElementTable& table, const IsotropicElasticity& material,
                       bool mean_dilation);

  const IsotropicElasticity& material() const { return material_; }
  const ElementTable& table() const { return table_; }
  bool mean_dilation() const { return mean_dilation_; }

  /// B at quadrature point q of cell c (3 x 2n), in Voigt form (eps_xx, eps_yy, 2 eps_xy).
  void strain_operator(int c, int q, StrainOperator& B) const;
  /// B of cell c from its n shape-function gradients at one point, or from their weighted
  /// average over part of the cell (B is affine in them, so that is the average of B there).
  void strain_operator_of(int c, const Eigen::Vector2d* gradients, StrainOperator& B) const;
  /// The cell stiffness matrix (2n x 2n).
  void cell_matrix(int c, Eigen::MatrixXd& K) const;
  /// The matrices of cells [first, last), computed in parallel into their own slots (so the
  /// result does not depend on the thread count): block(c) is cell first + c's column-major
  /// 2n x 2n matrix. Assembly works through the mesh in such chunks to bound the memory.
  struct CellMatrices {
    int first = 0;
    std::vector<std::size_t> offset;
    std::vector<double> data;
    Eigen::Map<const Eigen::MatrixXd> block(int c, int size) const {
      return {data.data() + offset[c - first], size, size};
    }
  };
  CellMatrices cell_matrices(int first, int last, int threads) const;
  CellMatrices all_cell_matrices(int threads) const {
    return cell_matrices(0, table_.mesh().num_cells(), threads);
  }
  /// Area-weighted mean stress of cell c for the cell's DOF vector u (2n).
  Eigen::Vector3d mean_stress(int c, const Eigen::VectorXd& u) const;
  /// The cell mean of the strain operator, (1/|c|) sum_q w_q B_q (3 x 2n): the mean strain of a
  /// DOF vector, hence its mean stress (D times it) and mean dilatation (rows 0 + 1). Kept per
  /// cell, it lets a solve release the element table's point values before the factorization.
  StrainOperator mean_strain_operator(int c) const;
  struct MeanStrainOperators {
    std::vector<std::size_t> offset;
    std::vector<double> data;
    Eigen::Map<const StrainOperator> block(int c) const {
      return {data.data() + offset[c], 3,
              static_cast<Eigen::Index>((offset[c + 1] - offset[c]) / 3)};
    }
  };
  MeanStrainOperators all_mean_strain_operators(int threads) const;
  /// Cell c's mean stress from its kept mean strain operator: D times the operator times u.
  Eigen::Vector3d mean_stress(const MeanStrainOperators& kept, int c,
                              const Eigen::VectorXd& u) const {
    return material_.D() * (kept.block(c) * u);
  }

 private:
  /// sum_q w_q B_q^T D B_q with B formed at every point (any strain operator: B-bar).
  void strain_operator_stiffness(int c, Eigen::MatrixXd& K) const;
  void add_vem_stabilization(int c, Eigen::MatrixXd& K) const;

  const ElementTable& table_;
  IsotropicElasticity material_;
  bool mean_dilation_;
};

}  // namespace vorodg
