#include "dynamics/GlobalTimeStep.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>

#include "core/util/Errors.hpp"
#include "core/util/Random.hpp"

namespace vorodg {
namespace {

struct Ritz {
  double theta = 0.0;
  double residual = 0.0;
};

/// Top Ritz value of the k x k Lanczos tridiagonal (alpha, beta) and its residual
/// beta_k |last component of its eigenvector|.
Ritz top_ritz(const std::vector<double>& alpha, const std::vector<double>& beta) {
  const Eigen::Index k = static_cast<Eigen::Index>(alpha.size());
  Eigen::VectorXd diag = Eigen::Map<const Eigen::VectorXd>(alpha.data(), k);
  Eigen::VectorXd sub = Eigen::Map<const Eigen::VectorXd>(beta.data(), k - 1);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig;
  eig.computeFromTridiagonal(diag, sub, Eigen::ComputeEigenvectors);
  return {eig.eigenvalues()[k - 1], std::abs(beta[k - 1] * eig.eigenvectors()(k - 1, k - 1))};
}

const Eigen::VectorXd& checked_masses(const Eigen::VectorXd& node_masses, const SplitDofMap& dofs) {
  if (2 * node_masses.size() != dofs.num_dofs())
    throw InputError("global time step: " + std::to_string(node_masses.size()) +
                     " node masses for " + std::to_string(dofs.num_nodes()) + " nodes");
  return node_masses;
}

}  // namespace

GlobalTimeStep::GlobalTimeStep(InternalForce& force, const SplitDofMap& dofs,
                               const Eigen::VectorXd& node_masses, const StableTimeStep& bound,
                               const LanczosOptions& options, const InterfaceCoupling* coupling)
    : GlobalTimeStep(
          [&](const Eigen::VectorXd& x, Eigen::VectorXd& Kx) {
            force.compute(dofs, x, Kx, options.threads);
            if (coupling) {  // K_F x: add_forces gives -K_F x
              Eigen::VectorXd coupled = Eigen::VectorXd::Zero(x.size());
              coupling->add_forces(x, coupled);
              Kx -= coupled;
            }
          },
          checked_masses(node_masses, dofs),
          bound.max_eigenvalue() + (coupling ? coupling->eigenvalue_bound(node_masses) : 0.0),
          options) {}

GlobalTimeStep::GlobalTimeStep(const Stiffness& stiffness, const Eigen::VectorXd& node_masses,
                               double cap, const LanczosOptions& options) {
  const Eigen::Index n = 2 * node_masses.size();
  Eigen::VectorXd scale(n);  // M^-1/2 per DOF
  for (Eigen::Index i = 0; i < n; ++i) scale[i] = 1.0 / std::sqrt(node_masses[i / 2]);
  Random random(options.seed);
  Eigen::VectorXd q(n), q_prev = Eigen::VectorXd::Zero(n), w(n), f(n);
  for (Eigen::Index i = 0; i < n; ++i) q[i] = random.uniform(-1.0, 1.0);
  q /= q.norm();
  std::vector<double> alpha, beta;
  double beta_prev = 0.0;
  Ritz ritz;
  for (int j = 0; j < options.max_iterations; ++j) {
    stiffness(scale.cwiseProduct(q), f);
    w = scale.cwiseProduct(f) - beta_prev * q_prev;
    alpha.push_back(q.dot(w));
    w -= alpha.back() * q;
    beta.push_back(w.norm());
    iterations_ = j + 1;
    ritz = top_ritz(alpha, beta);
    if (ritz.residual <= options.tolerance * ritz.theta || beta.back() == 0.0) {
      converged_ = true;
      break;
    }
    q_prev.swap(q);
    q = w / beta.back();
    beta_prev = beta.back();
  }
  theta_ = ritz.theta;
  residual_ = ritz.residual;
  const double lambda = std::min(theta_ + residual_, cap);
  critical_ = 2.0 / std::sqrt(lambda);
}

double GlobalTimeStep::step(double safety) const {
  require_parameter(safety > 0.0 && safety <= 1.0, "time step safety factor", safety, "in (0, 1]");
  return safety * critical_;
}

}  // namespace vorodg
