#pragma once
// The interface terms of the DG formulations, as small dense operators on the DOFs of an
// interface's two cells (cell 1's DOFs, then cell 2's):
//   jump(t):    [u] at the point a + t (b - a) of the edge (2 x m), linear in t;
//   mean_jump:  the edge mean of [u] (2 x m), what a constant traction integrates against;
//   traction:   {sigma(u)}_w n = (w_1 sigma_1 + w_2 sigma_2) n with cell 1's normal (2 x m);
//               w = (1/2, 1/2) is the plain average, other weights (summing to 1) keep the term
//               consistent. Each cell's stress on the edge is one of (TractionKind):
//                 point: its own stress at the point, from the shape functions' one-sided limit;
//                 fan:   its own stress averaged over its fan triangle on the edge, i.e. the
//                        stress its bulk quadrature sees next to the edge;
//                 mean:  its mean stress (the report's Eq. 29).
//               All three are exact for linear fields, so every choice passes the patch test.
#include <Eigen/Core>
#include <vector>

#include "core/element/ElasticityIntegrator.hpp"
#include "interfaces/DgSpace.hpp"

namespace vorodg {

using InterfaceOperator = Eigen::Matrix<double, 2, Eigen::Dynamic>;
using StressOperator = Eigen::Matrix<double, 3, Eigen::Dynamic>;

enum class TractionKind { point, fan, mean };

class InterfaceOperators {
 public:
  InterfaceOperators(const DgSpace& space, const ElasticityIntegrator& integrator,
                     const ElementTable& table);

  const DgSpace& space() const { return space_; }
  /// Global DOFs of an interface's two cells, in operator column order.
  std::vector<int> dofs(const Interface& f) const;
  InterfaceOperator jump(const Interface& f, double t) const;
  InterfaceOperator mean_jump(const Interface& f) const { return jump(f, 0.5); }
  /// {sigma(u)}_w n at edge point t with each cell's stress of the given kind.
  InterfaceOperator traction(const Interface& f, double t, TractionKind kind,
                             const Eigen::Vector2d& w = kPlainAverage) const;
  /// {sigma(u)} n with each cell's mean stress (constant along the edge).
  InterfaceOperator mean_traction(const Interface& f) const {
    return traction(f, 0.5, TractionKind::mean);
  }
  /// {sigma(u)} n with each cell's own stress at edge point t (one-sided gradients).
  InterfaceOperator point_traction(const Interface& f, double t) const {
    return traction(f, t, TractionKind::point);
  }
  /// Cell c's stress operator (3 x 2n) on its edge k (vertex k to k + 1), at the point a fraction
  /// `along` of the way (point; fan and mean are constant along the edge).
  StressOperator edge_stress(int c, int k, double along, TractionKind kind) const;
  /// Cell c's fan stresses on all its edges (or only on edge `only`) in one pass over its
  /// quadrature points.
  std::vector<StressOperator> fan_stresses(int c, int only = -1) const;
  /// Cell c's outward unit normal on its edge k.
  Eigen::Vector2d edge_normal(int c, int k) const;
  /// Maps a Voigt stress to the traction on a surface with normal n.
  static Eigen::Matrix<double, 2, 3> traction_map(const Eigen::Vector2d& n);
  inline static const Eigen::Vector2d kPlainAverage{0.5, 0.5};
  /// Mean stress operator of cell c (3 x 2n): sigma_mean = D * mean(B) u_c.
  const StressOperator& mean_stress_operator(int c) const { return mean_stress_[c]; }

  // Blocks of the interface terms on the interface's two cells' DOFs, with the two-point rule
  // (exact: jumps are linear along the edge, and fan and mean stresses constant on it).
  /// eps int_F [u].[v].
  Eigen::MatrixXd penalty_block(const Interface& f, double eps) const;
  /// int_F {sigma(u)}_w n . [v] (v the rows, u the columns).
  Eigen::MatrixXd consistency_block(const Interface& f, TractionKind kind,
                                    const Eigen::Vector2d& w) const;
  /// The symmetric interior-penalty block: penalty_block - C - C^T, C the consistency block.
  Eigen::MatrixXd sipg_block(const Interface& f, double eps, TractionKind kind,
                             const Eigen::Vector2d& w) const;

 private:
  const DgSpace& space_;
  const ElasticityIntegrator& integrator_;
  const ElementTable& table_;
  StressOperator point_stress(int c, int k, double along) const;
  StressOperator fan_stress(int c, int k) const;

  std::vector<StressOperator> mean_stress_;
};

}  // namespace vorodg
