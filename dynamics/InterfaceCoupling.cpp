#include "dynamics/InterfaceCoupling.hpp"

#include <cmath>
#include <string>

#include "core/util/Errors.hpp"

namespace vorodg {

InterfaceCoupling::InterfaceCoupling(const ElementTable& table,
                                     const ElasticityIntegrator& integrator,
                                     const ElasticityIntegrator::CellMatrices& cells,
                                     const SplitDofMap& dofs, double kp, int threads)
    : num_dofs_(dofs.num_dofs()) {
  require_parameter(std::isfinite(kp) && kp > 0.0, "interface coupling: penalty k_p", kp, "> 0");
  space_ = std::make_unique<DgSpace>(table.mesh(), dofs);
  ops_ = std::make_unique<InterfaceOperators>(*space_, integrator, table);
  penalty_ = std::make_unique<InterfacePenalty>(*ops_, integrator, cells, PenaltyScaling::coercive,
                                                kp, false, TractionKind::fan, threads);
  const auto& faces = space_->interfaces();
  blocks_.resize(faces.size());
  dofs_.resize(faces.size());
#pragma omp parallel for schedule(dynamic, 64) num_threads(std::max(threads, 1))
  for (int i = 0; i < static_cast<int>(faces.size()); ++i) {
    blocks_[i] =
        ops_->sipg_block(faces[i], penalty_->eps(i), TractionKind::fan, penalty_->weights(i));
    dofs_[i] = ops_->dofs(faces[i]);
  }
}

double InterfaceCoupling::add_forces(const Eigen::VectorXd& u, Eigen::VectorXd& f) const {
  if (u.size() != num_dofs_ || f.size() != num_dofs_)
    throw InputError("interface coupling: " + std::to_string(u.size()) + " displacements and " +
                     std::to_string(f.size()) + " forces: expected " + std::to_string(num_dofs_) +
                     " each");
  double energy = 0.0;
  Eigen::VectorXd local, force;
  for (std::size_t i = 0; i < blocks_.size(); ++i) {
    const std::vector<int>& d = dofs_[i];
    // Displacements relative to the first vertex's: K_F annihilates translations, so a body
    // that has moved far feels no round-off of its translation (as in InternalForce).
    local.resize(d.size());
    for (std::size_t k = 0; k < d.size(); ++k) local[k] = u[d[k]] - u[d[k % 2]];
    force.noalias() = blocks_[i] * local;
    energy += 0.5 * local.dot(force);
    // Self-equilibrated: the last vertex takes minus the others' sum, so no momentum is made.
    const std::size_t last = d.size() - 2;
    double sx = 0.0, sy = 0.0;
    for (std::size_t k = 0; k < last; k += 2) sx += force[k], sy += force[k + 1];
    force[last] = -sx, force[last + 1] = -sy;
    for (std::size_t k = 0; k < d.size(); ++k) f[d[k]] -= force[k];
  }
  return energy;
}

double InterfaceCoupling::eigenvalue_bound(const Eigen::VectorXd& node_masses) const {
  Eigen::VectorXd row = Eigen::VectorXd::Zero(num_dofs_);
  for (std::size_t i = 0; i < blocks_.size(); ++i) {
    const std::vector<int>& d = dofs_[i];
    for (std::size_t a = 0; a < d.size(); ++a)
      for (std::size_t b = 0; b < d.size(); ++b)
        row[d[a]] +=
            std::abs(blocks_[i](a, b)) / std::sqrt(node_masses[d[a] / 2] * node_masses[d[b] / 2]);
  }
  return row.size() ? row.maxCoeff() : 0.0;
}

}  // namespace vorodg
