#pragma once
// Prescribed displacements imposed by elimination: the DOFs of every vertex (or vertex copy) on
// a Dirichlet side are fixed to the data there (the shape functions are Kronecker-delta at
// vertices); the rest are numbered as the free unknowns of the linear system.
#include <Eigen/Core>
#include <vector>

#include "core/element/LoadIntegrator.hpp"
#include "core/mesh/PolygonMesh.hpp"
#include "core/problem/BoundaryValueProblem.hpp"

namespace vorodg {

class DirichletConstraints {
 public:
  /// Fixes the DOFs first_dof(c, k), +1 of every cell's vertex on a Dirichlet side. Throws
  /// InputError if the problem has no Dirichlet side (rigid-body motions would be free).
  DirichletConstraints(const PolygonMesh& mesh, const BoundaryValueProblem& problem,
                       const DofOf& first_dof, int num_dofs);

  int num_free() const { return static_cast<int>(free_.size()); }
  /// Index of a global DOF among the free ones, or -1 if it is prescribed.
  int free_index(int dof) const { return free_index_[dof]; }
  int free_dof(int k) const { return free_[k]; }
  /// The prescribed values (zero at free DOFs).
  const Eigen::VectorXd& prescribed() const { return prescribed_; }
  /// Full DOF vector from the free values and the prescribed ones.
  Eigen::VectorXd expand(const Eigen::VectorXd& free_values) const;
  /// The free entries of a full vector.
  Eigen::VectorXd restrict(const Eigen::VectorXd& full) const;

 private:
  std::vector<int> free_index_, free_;
  Eigen::VectorXd prescribed_;
};

}  // namespace vorodg
