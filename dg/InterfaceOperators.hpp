#pragma once
// The interface terms of the DG formulations, as small dense operators on the DOFs of an
// interface's two cells (cell 1's DOFs, then cell 2's):
//   jump(t):    [u] at the point a + t (b - a) of the edge (2 x m), linear in t;
//   mean_jump:  the edge mean of [u] (2 x m), what a constant traction integrates against;
//   traction:   {sigma(u)} n, the average of the two cells' stress times cell 1's normal (2 x m),
//               from each cell's mean stress or its own stress at the point.
#include <Eigen/Core>
#include <vector>

#include "core/element/ElasticityIntegrator.hpp"
#include "dg/DgSpace.hpp"

namespace vorodg {

using InterfaceOperator = Eigen::Matrix<double, 2, Eigen::Dynamic>;

class InterfaceOperators {
 public:
  InterfaceOperators(const DgSpace& space, const ElasticityIntegrator& integrator,
                     const ElementTable& table);

  /// Global DOFs of an interface's two cells, in operator column order.
  std::vector<int> dofs(const Interface& f) const;
  InterfaceOperator jump(const Interface& f, double t) const;
  InterfaceOperator mean_jump(const Interface& f) const { return jump(f, 0.5); }
  /// {sigma(u)} n with each cell's mean stress (constant along the edge).
  InterfaceOperator mean_traction(const Interface& f) const;
  /// {sigma(u)} n with each cell's own stress at edge point t (one-sided gradients).
  InterfaceOperator point_traction(const Interface& f, double t) const;
  /// Mean stress operator of cell c (3 x 2n): sigma_mean = D * mean(B) u_c.
  const Eigen::Matrix<double, 3, Eigen::Dynamic>& mean_stress_operator(int c) const {
    return mean_stress_[c];
  }

 private:
  /// Maps a Voigt stress to the traction on a surface with normal n.
  static Eigen::Matrix<double, 2, 3> traction_map(const Eigen::Vector2d& n);

  const DgSpace& space_;
  const ElasticityIntegrator& integrator_;
  const ElementTable& table_;
  std::vector<Eigen::Matrix<double, 3, Eigen::Dynamic>> mean_stress_;
};

}  // namespace vorodg
