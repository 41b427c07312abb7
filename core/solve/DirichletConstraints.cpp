#include "core/solve/DirichletConstraints.hpp"

#include "core/util/Errors.hpp"

namespace vorodg {

DirichletConstraints::DirichletConstraints(const PolygonMesh& mesh,
                                           const BoundaryValueProblem& problem,
                                           const DofOf& first_dof, int num_dofs) {
  if (!problem.has_dirichlet_side())
    throw InputError("problem '" + problem.name() +
                     "' prescribes no displacement on any side: the system is singular "
                     "(rigid-body motions are free)");
  const std::vector<char> on_dirichlet = dirichlet_vertices(mesh, problem);
  std::vector<char> fixed(num_dofs, 0);
  prescribed_ = Eigen::VectorXd::Zero(num_dofs);
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto loop = mesh.cell_vertices(c);
    for (std::size_t k = 0; k < loop.size(); ++k) {
      if (!on_dirichlet[loop[k]]) continue;
      const int d = first_dof(c, static_cast<int>(k));
      fixed[d] = fixed[d + 1] = 1;
      prescribed_.segment<2>(d) = problem.dirichlet_value(mesh.vertex(loop[k]));
    }
  }
  free_index_.assign(num_dofs, -1);
  for (int d = 0; d < num_dofs; ++d)
    if (!fixed[d]) {
      free_index_[d] = static_cast<int>(free_.size());
      free_.push_back(d);
    }
}

Eigen::VectorXd DirichletConstraints::expand(const Eigen::VectorXd& free_values) const {
  Eigen::VectorXd u = prescribed_;
  for (int k = 0; k < num_free(); ++k) u[free_[k]] = free_values[k];
  return u;
}

Eigen::VectorXd DirichletConstraints::restrict(const Eigen::VectorXd& full) const {
  Eigen::VectorXd out(num_free());
  for (int k = 0; k < num_free(); ++k) out[k] = full[free_[k]];
  return out;
}

}  // namespace vorodg
