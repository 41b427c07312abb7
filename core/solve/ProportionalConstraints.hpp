#pragma once
// Prescribed DOFs whose values grow with one load parameter: u_p = lambda * reference_p (a support
// is a reference of zero). The rest are numbered as the free unknowns. This is how a
// displacement-controlled test loads a body: the machine's stroke is lambda, and the force it
// needs is the work-conjugate of lambda, sum_p reaction_p * reference_p.
#include <Eigen/Core>
#include <vector>

namespace vorodg {

struct PrescribedDof {
  int dof;
  double reference;  // value at lambda = 1
};

class ProportionalConstraints {
 public:
  /// Throws InputError for a DOF out of range or prescribed twice with different references.
  ProportionalConstraints(const std::vector<PrescribedDof>& prescribed, int num_dofs);

  int num_dofs() const { return static_cast<int>(free_index_.size()); }
  int num_free() const { return static_cast<int>(free_.size()); }
  /// Index among the free DOFs, or -1 if prescribed.
  int free_index(int dof) const { return free_index_[dof]; }
  /// The reference values on all DOFs (zero at free ones).
  const Eigen::VectorXd& reference() const { return reference_; }
  /// The full vector from the free values and lambda.
  Eigen::VectorXd expand(const Eigen::VectorXd& free_values, double lambda) const;
  /// The free entries of a full vector.
  Eigen::VectorXd restrict(const Eigen::VectorXd& full) const;
  /// sum_p full_p reference_p: the work-conjugate of lambda (for a force vector).
  double conjugate(const Eigen::VectorXd& full) const { return full.dot(reference_); }

 private:
  std::vector<int> free_index_, free_;
  Eigen::VectorXd reference_;
};

}  // namespace vorodg
