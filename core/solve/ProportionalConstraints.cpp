#include "core/solve/ProportionalConstraints.hpp"

#include <string>

#include "core/util/Errors.hpp"

namespace vorodg {

ProportionalConstraints::ProportionalConstraints(const std::vector<PrescribedDof>& prescribed,
                                                 int num_dofs)
    : free_index_(num_dofs, 0), reference_(Eigen::VectorXd::Zero(num_dofs)) {
  std::vector<char> fixed(num_dofs, 0);
  for (const PrescribedDof& p : prescribed) {
    if (p.dof < 0 || p.dof >= num_dofs)
      throw InputError("prescribed DOF " + std::to_string(p.dof) + ": expected 0 .. " +
                       std::to_string(num_dofs - 1));
    if (fixed[p.dof] && reference_[p.dof] != p.reference)
      throw InputError("DOF " + std::to_string(p.dof) +
                       " is prescribed twice, to different values");
    fixed[p.dof] = 1;
    reference_[p.dof] = p.reference;
  }
  for (int d = 0; d < num_dofs; ++d) {
    free_index_[d] = fixed[d] ? -1 : static_cast<int>(free_.size());
    if (!fixed[d]) free_.push_back(d);
  }
}

Eigen::VectorXd ProportionalConstraints::expand(const Eigen::VectorXd& free_values,
                                                double lambda) const {
  Eigen::VectorXd full = lambda * reference_;
  for (std::size_t k = 0; k < free_.size(); ++k) full[free_[k]] = free_values[k];
  return full;
}

Eigen::VectorXd ProportionalConstraints::restrict(const Eigen::VectorXd& full) const {
  return full(free_);
}

}  // namespace vorodg
