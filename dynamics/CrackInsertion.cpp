#include "dynamics/CrackInsertion.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "core/util/Errors.hpp"
#include "fracture/FaceInsertion.hpp"

namespace vorodg {

CrackInsertion::CrackInsertion(const PolygonMesh& mesh, const ElasticityIntegrator& integrator,
                               const MohrCoulomb& criterion, std::vector<char> eligible,
                               int threads)
    : mesh_(mesh), criterion_(criterion) {
  if (static_cast<int>(eligible.size()) != mesh.num_edges())
    throw InputError("crack insertion: " + std::to_string(eligible.size()) +
                     " edge flags, expected " + std::to_string(mesh.num_edges()));
  const auto strain = integrator.all_mean_strain_operators(threads);
  const Eigen::Matrix3d& D = integrator.material().D();
  offset_.assign(mesh.num_cells() + 1, 0);
  for (int c = 0; c < mesh.num_cells(); ++c)
    offset_[c + 1] = offset_[c] + 6 * static_cast<std::size_t>(mesh.cell_size(c));
  stress_operator_.resize(offset_.back());
  for (int c = 0; c < mesh.num_cells(); ++c)
    Eigen::Map<Eigen::MatrixXd>(stress_operator_.data() + offset_[c], 3, 2 * mesh.cell_size(c)) =
        D * strain.block(c);
  tangent_.reserve(mesh.num_edges());
  for (const MeshEdge& e : mesh.edges())
    tangent_.push_back((mesh.vertex(e.v1) - mesh.vertex(e.v0)).normalized());
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const MeshEdge& edge = mesh.edge(e);
    if (eligible[e] && edge.cell1 >= 0) checked_.push_back({e, edge.cell0, edge.cell1, 1.0});
  }
}

void CrackInsertion::vary(const MaterialVariation& variation) {
  if (variation.empty()) return;
  for (int c = 0; c < mesh_.num_cells(); ++c)
    for (std::size_t i = offset_[c]; i < offset_[c + 1]; ++i)
      stress_operator_[i] *= variation.stiffness[c];
  const std::vector<double> strength = variation.edge_strength(mesh_);
  for (Checked& k : checked_) k.strength = strength[k.edge];
}

Eigen::Matrix3Xd CrackInsertion::cell_stresses(const SplitDofMap& dofs, const Eigen::VectorXd& u,
                                               int threads, std::span<const double> local) const {
  const int cells = mesh_.num_cells();
  const std::size_t pairs = 2 * std::size_t(mesh_.offsets().back());
  if (!local.empty() && local.size() != pairs)
    throw InputError("crack insertion: " + std::to_string(local.size()) +
                     " local displacements: expected 2 per (cell, vertex) pair, " +
                     std::to_string(pairs));
  Eigen::Matrix3Xd sigma(3, cells);
#pragma omp parallel for schedule(static, 256) num_threads(std::max(threads, 1))
  for (int c = 0; c < cells; ++c) {
    const double* S = stress_operator_.data() + offset_[c];
    Eigen::Vector3d s = Eigen::Vector3d::Zero();
    if (frames_) {
      // In the cell's turning frame, where the edges keep their reference normals.
      thread_local std::vector<double> turned;
      const double* l = local.data() + 2 * std::size_t(mesh_.offsets()[c]);
      if (local.empty()) {
        turned.resize(2 * mesh_.cell_size(c));  // within its capacity after the largest cell
        frames_->local_displacements(c, dofs, u, turned.data());
        l = turned.data();
      }
      for (int k = 0; k < mesh_.cell_size(c); ++k, S += 6)
        s += Eigen::Map<const Eigen::Matrix<double, 3, 2>>(S) *
             Eigen::Map<const Eigen::Vector2d>(l + 2 * k);
    } else {
      for (int k = 0; k < mesh_.cell_size(c); ++k, S += 6) {
        const int node = dofs.node(c, k);
        s += Eigen::Map<const Eigen::Matrix<double, 3, 2>>(S) * u.segment<2>(2 * node);
      }
    }
    sigma.col(c) = s;
  }
  return sigma;
}

Eigen::Vector2d CrackInsertion::traction(const Eigen::Matrix3Xd& stresses, int e) const {
  const MeshEdge& edge = mesh_.edge(e);
  const Eigen::Vector3d s = 0.5 * (stresses.col(edge.cell0) + stresses.col(edge.cell1));
  const Eigen::Vector2d& t = tangent_[e];
  return face_traction(s, Eigen::Vector2d(t.y(), -t.x()), t);
}

std::vector<CrackInsertion::Failure> CrackInsertion::failing_edges(
    const SplitDofMap& dofs, const Eigen::VectorXd& u, const std::vector<char>& cracked,
    int threads, std::span<const double> local) const {
  const Eigen::Matrix3Xd sigma = cell_stresses(dofs, u, threads, local);
  // Each cell's worst plane first: an edge whose two cells lie below its strength factor on
  // every plane cannot fail on its own (the criterion's safe set is convex in the stress, and
  // the edge sees the cells' mean), so only the others are evaluated. The margin keeps the
  // screen clear of round-off: an edge it passes has a utilization below 1 - 1e-9, which no
  // rounding of the traction brings to 1. The failing edges are the same as without it.
  constexpr double kScreenMargin = 1.0 - 1e-9;
  // (A NaN stress screens nothing: the criterion then refuses it.)
  std::vector<double> worst(sigma.cols());
  for (Eigen::Index c = 0; c < sigma.cols(); ++c)
    worst[c] = criterion_.worst_plane_factor(sigma(0, c), sigma(1, c), sigma(2, c));
  std::vector<Failure> failing;
  for (const Checked& k : checked_) {
    if (cracked[k.edge]) continue;
    if (std::max(worst[k.cell0], worst[k.cell1]) < kScreenMargin * k.strength) continue;
    const Eigen::Vector2d t = traction(sigma, k.edge);
    if (face_utilization(criterion_, t, k.strength) >= 1.0) failing.push_back({k.edge, t});
  }
  return failing;
}

}  // namespace vorodg
