#include "dynamics/InterfaceCoupling.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/io/StateArchive.hpp"
#include "core/quadrature/TriangleRule.hpp"
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
  for (const auto& d : dofs_)
    largest_block_ = std::max(largest_block_, static_cast<Eigen::Index>(d.size()));
  active_.assign(faces.size(), 1);
  interface_of_edge_.assign(table.mesh().num_edges(), -1);
  flux_.resize(faces.size());
  last_flux_.assign(faces.size(), Eigen::Vector4d::Zero());
  jump_compact_.resize(faces.size());
  jump_columns_.resize(faces.size());
  const SegmentRule& rule = gauss2_segment();
  for (std::size_t i = 0; i < faces.size(); ++i) {
    interface_of_edge_[faces[i].edge] = static_cast<int>(i);
    const Eigen::Index m = static_cast<Eigen::Index>(dofs_[i].size());
    flux_[i].resize(4, m);
    Eigen::Matrix<double, 4, Eigen::Dynamic> jump(4, m);
    for (int q = 0; q < 2; ++q) {
      const InterfaceOperator J = ops_->jump(faces[i], rule.t[q]);
      jump.middleRows<2>(2 * q) = J;
      flux_[i].middleRows<2>(2 * q) =
          ops_->traction(faces[i], rule.t[q], TractionKind::fan, penalty_->weights(i)) -
          penalty_->eps(i) * J;
    }
    // The jump's nonzero columns, in column order (a shape function is linear along an edge).
    int found = 0;
    for (Eigen::Index c = 0; c < m; ++c)
      if (jump.col(c).cwiseAbs().maxCoeff() > 0.0) {
        if (found == 8)
          throw NumericalError("interface coupling: interface " + std::to_string(i) +
                               ": its jump involves more than the edge's 8 end DOFs");
        jump_columns_[i][found] = static_cast<int>(c);
        jump_compact_[i].col(found++) = jump.col(c);
      }
    for (; found < 8; ++found) {  // an end DOF whose jump entries vanish: a zero column
      jump_columns_[i][found] = 0;
      jump_compact_[i].col(found).setZero();
    }
  }
}

void InterfaceCoupling::deactivate(int i) {
  if (i < 0 || i >= num_interfaces() || !active_[i])
    throw InputError("interface coupling: interface " + std::to_string(i) + " is not active");
  active_[i] = 0;
}

Eigen::VectorXd InterfaceCoupling::local(int i, const Eigen::VectorXd& u) const {
  const std::vector<int>& d = dofs_[i];
  Eigen::VectorXd x(d.size());
  for (std::size_t k = 0; k < d.size(); ++k) x[k] = u[d[k]] - u[d[k % 2]];
  return x;
}

double InterfaceCoupling::energy(int i, const Eigen::VectorXd& u) const {
  const Eigen::VectorXd x = local(i, u);
  return 0.5 * x.dot(blocks_[i] * x);
}

std::array<Eigen::Vector2d, 2> InterfaceCoupling::traction(int i, const Eigen::VectorXd& u) const {
  const Eigen::Vector4d t = flux_[i] * local(i, u);
  return {t.head<2>(), t.tail<2>()};
}

std::array<Eigen::Vector2d, 2> InterfaceCoupling::opening(int i, const Eigen::VectorXd& u) const {
  const Eigen::VectorXd x = local(i, u);
  Eigen::Matrix<double, 8, 1> ends;
  for (int c = 0; c < 8; ++c) ends[c] = x[jump_columns_[i][c]];
  const Eigen::Vector4d j = jump_compact_[i] * ends;
  return {-j.head<2>(), -j.tail<2>()};
}

double InterfaceCoupling::add_forces(const Eigen::VectorXd& u, Eigen::VectorXd& f) const {
  if (u.size() != num_dofs_ || f.size() != num_dofs_)
    throw InputError("interface coupling: " + std::to_string(u.size()) + " displacements and " +
                     std::to_string(f.size()) + " forces: expected " + std::to_string(num_dofs_) +
                     " each");
  const SegmentRule& rule = gauss2_segment();
  double energy = 0.0;
  // One buffer of the largest block's size: the loop allocates nothing (cells differ in size).
  thread_local Eigen::VectorXd local_buffer, force_buffer;
  local_buffer.resize(largest_block_);
  force_buffer.resize(largest_block_);
  for (std::size_t i = 0; i < blocks_.size(); ++i) {
    if (!active_[i]) continue;
    const std::vector<int>& d = dofs_[i];
    const Eigen::Index m = static_cast<Eigen::Index>(d.size());
    auto local = local_buffer.head(m);
    auto force = force_buffer.head(m);
    // Displacements relative to the first vertex's: K_F annihilates translations, so a body
    // that has moved far feels no round-off of its translation (as in InternalForce).
    for (Eigen::Index k = 0; k < m; ++k) local[k] = u[d[k]] - u[d[k % 2]];
    // K_F = sum_q w_q (eps J_q^T J_q - J_q^T T_q - T_q^T J_q), with the flux Phi_q = T_q - eps J_q:
    // K_F u = -sum_q w_q (J_q^T (phi_q + eps j_q) + Phi_q^T j_q), phi = Phi u, j = J u. Four
    // rows each way instead of the m x m block (exact: the two-point rule integrates the
    // blocks exactly).
    const std::array<int, 8>& cols = jump_columns_[i];
    Eigen::Matrix<double, 8, 1> ends;
    for (int c = 0; c < 8; ++c) ends[c] = local[cols[c]];
    const Eigen::Vector4d phi = flux_[i] * local;
    const Eigen::Vector4d j = jump_compact_[i] * ends;
    last_flux_[i] = phi;
    const double eps = penalty_->eps(i), length = space_->interfaces()[i].length;
    Eigen::Vector4d wj, wphi;
    for (int q = 0; q < 2; ++q) {
      const double w = rule.weights[q] * length;
      wj.segment<2>(2 * q) = w * j.segment<2>(2 * q);
      wphi.segment<2>(2 * q) = w * (phi.segment<2>(2 * q) + eps * j.segment<2>(2 * q));
    }
    force.noalias() = -(flux_[i].transpose() * wj);
    const Eigen::Matrix<double, 8, 1> end_force = jump_compact_[i].transpose() * wphi;
    for (int c = 0; c < 8; ++c) force[cols[c]] -= end_force[c];
    energy -= 0.5 * (wj.dot(phi) + wphi.dot(j));
    // Self-equilibrated: the last vertex takes minus the others' sum, so no momentum is made.
    const Eigen::Index last = m - 2;
    double sx = 0.0, sy = 0.0;
    for (Eigen::Index k = 0; k < last; k += 2) sx += force[k], sy += force[k + 1];
    force[last] = -sx, force[last + 1] = -sy;
    for (Eigen::Index k = 0; k < m; ++k) f[d[k]] -= force[k];
  }
  return energy;
}

std::array<Eigen::Vector2d, 2> InterfaceCoupling::last_traction(int i) const {
  return {last_flux_[i].head<2>(), last_flux_[i].tail<2>()};
}

double InterfaceCoupling::eigenvalue_bound(const Eigen::VectorXd& node_masses) const {
  Eigen::VectorXd row = Eigen::VectorXd::Zero(num_dofs_);
  for (std::size_t i = 0; i < blocks_.size(); ++i) {
    if (!active_[i]) continue;
    const std::vector<int>& d = dofs_[i];
    for (std::size_t a = 0; a < d.size(); ++a)
      for (std::size_t b = 0; b < d.size(); ++b)
        row[d[a]] +=
            std::abs(blocks_[i](a, b)) / std::sqrt(node_masses[d[a] / 2] * node_masses[d[b] / 2]);
  }
  return row.size() ? row.maxCoeff() : 0.0;
}

void InterfaceCoupling::archive(StateArchive& a) {
  a.vector("coupling.active", active_);
  a.vector("coupling.last_flux", last_flux_);
}

}  // namespace vorodg
