#pragma once
// The discrete trace inequality of each cell, the constant a coercive interior penalty is built
// from (docs/dg.md "A penalty from the discrete space"). For cell K and one of its edges F,
//   C_{K,F} = max over v in V_K, v not rigid, of ||sigma_K(v) n||^2_{F,h} / a_K(v, v),
// where ||.||_{F,h} is the two-point Gauss norm the interface terms are assembled with and
// sigma_K(v) is the cell's stress on the edge as the interface terms take it (TractionKind). Rigid
// motions have zero traction and zero energy, so the quotient lives on their complement: with R an
// orthonormal basis of the rigid modes, K + s R R^T is positive definite and C_{K,F} is the largest
// eigenvalue of G_F (K + s R R^T)^{-1} G_F^T, a 4 x 4 (point) or 2 x 2 (fan, mean: constant along
// the edge) matrix, where G_F^T G_F is the traction norm on F.
#include <Eigen/Core>
#include <vector>

#include "core/element/ElasticityIntegrator.hpp"
#include "interfaces/InterfaceOperators.hpp"

namespace vorodg {

class TraceConstants {
 public:
  /// Computes every cell's constants from its stiffness matrix (the DG bulk term) in parallel;
  /// the result does not depend on `threads`. Throws NumericalError naming the cell if its
  /// stiffness has a zero-energy mode that is not a rigid motion.
  TraceConstants(const InterfaceOperators& ops, const ElasticityIntegrator::CellMatrices& stiffness,
                 TractionKind kind, int threads);

  /// C_{K,F} for cell c and its edge k (from the cell's vertex k to vertex k + 1).
  double constant(int c, int k) const { return constants_[offsets_[c] + k]; }
  TractionKind kind() const { return kind_; }

  /// C_{K,F} for one cell by the quotient's definition, without the rigid-mode shift: the
  /// dense generalized eigenproblem on the complement of the stiffness kernel (for tests).
  static std::vector<double> brute_force(const InterfaceOperators& ops,
                                         const ElasticityIntegrator& integrator, TractionKind kind,
                                         int c);

  /// The rows G_F of edge k of cell c (G_F^T G_F = the traction norm on F).
  static Eigen::MatrixXd traction_rows(const InterfaceOperators& ops, TractionKind kind, int c,
                                       int k);

 private:
  void compute_cell(const InterfaceOperators& ops, const Eigen::Ref<const Eigen::MatrixXd>& K,
                    int c);

  TractionKind kind_;
  std::vector<int> offsets_;
  std::vector<double> constants_;
};

}  // namespace vorodg
