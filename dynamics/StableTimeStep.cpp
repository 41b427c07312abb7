#include "dynamics/StableTimeStep.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>

#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"

namespace vorodg {

double StableTimeStep::cell_eigenvalue(const Eigen::MatrixXd& K,
                                       const Eigen::VectorXd& pair_masses) {
  const Eigen::Index n = pair_masses.size();
  Eigen::VectorXd scale(2 * n);
  for (Eigen::Index k = 0; k < n; ++k)
    scale[2 * k] = scale[2 * k + 1] = 1.0 / std::sqrt(pair_masses[k]);
  // M^-1/2 K M^-1/2, symmetrized against round-off in K.
  const Eigen::MatrixXd A = scale.asDiagonal() * (0.5 * (K + K.transpose())) * scale.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(A, Eigen::EigenvaluesOnly);
  return eig.eigenvalues().maxCoeff();
}

StableTimeStep::StableTimeStep(const PolygonMesh& mesh,
                               const ElasticityIntegrator::CellMatrices& matrices,
                               const LumpedMass& mass, int threads) {
  const int nc = mesh.num_cells();
  if (matrices.first != 0 || static_cast<int>(matrices.offset.size()) != nc + 1)
    throw InputError("stable time step: expected the cell matrices of all " + std::to_string(nc) +
                     " cells");
  lambda_.assign(nc, 0.0);
#pragma omp parallel for schedule(dynamic, 256) num_threads(std::max(threads, 1))
  for (int c = 0; c < nc; ++c) {
    const int n = mesh.cell_size(c);
    const auto m = mass.cell(c);
    lambda_[c] =
        cell_eigenvalue(matrices.block(c, 2 * n), Eigen::Map<const Eigen::VectorXd>(m.data(), n));
  }
  for (int c = 0; c < nc; ++c) {
    if (!(lambda_[c] > 0.0) || !std::isfinite(lambda_[c]))
      throw NumericalError("stable time step: cell " + std::to_string(c) +
                           ": expected a positive finite largest eigenvalue of M^-1 K, found " +
                           fmt(lambda_[c]));
    if (lambda_[c] > max_lambda_) max_lambda_ = lambda_[c], controlling_ = c;
  }
  critical_ = 2.0 / std::sqrt(max_lambda_);
}

double StableTimeStep::nodal_critical(const SplitDofMap& dofs, const LumpedMass& mass) const {
  std::vector<double> weighted(dofs.num_nodes(), 0.0);
  for (int c = 0; c < static_cast<int>(lambda_.size()); ++c)
    for (int k = 0; k < static_cast<int>(mass.cell(c).size()); ++k)
      weighted[dofs.node(c, k)] += lambda_[c] * mass.pair_mass(c, k);
  const Eigen::VectorXd m = mass.node_masses(dofs);
  double bound = 0.0;
  for (int i = 0; i < dofs.num_nodes(); ++i) bound = std::max(bound, weighted[i] / m[i]);
  return 2.0 / std::sqrt(bound);
}

double StableTimeStep::step(double safety) const {
  require_parameter(safety > 0.0 && safety <= 1.0, "time step safety factor", safety, "in (0, 1]");
  return safety * critical_;
}

}  // namespace vorodg
