#include "dynamics/CrackInsertion.hpp"

#include <algorithm>
#include <string>

#include "core/util/Errors.hpp"

namespace vorodg {

CrackInsertion::CrackInsertion(const PolygonMesh& mesh, const ElasticityIntegrator& integrator,
                               const MohrCoulomb& criterion, std::vector<char> eligible,
                               int threads)
    : mesh_(mesh),
      D_(integrator.material().D()),
      strain_(integrator.all_mean_strain_operators(threads)),
      criterion_(criterion),
      eligible_(std::move(eligible)) {
  if (static_cast<int>(eligible_.size()) != mesh.num_edges())
    throw InputError("crack insertion: " + std::to_string(eligible_.size()) +
                     " edge flags, expected " + std::to_string(mesh.num_edges()));
}

Eigen::Matrix3Xd CrackInsertion::cell_stresses(const SplitDofMap& dofs, const Eigen::VectorXd& u,
                                               int threads) const {
  const int cells = mesh_.num_cells();
  Eigen::Matrix3Xd sigma(3, cells);
#pragma omp parallel for schedule(static, 256) num_threads(std::max(threads, 1))
  for (int c = 0; c < cells; ++c) {
    const int n = mesh_.cell_size(c);
    Eigen::VectorXd uc(2 * n);
    for (int k = 0; k < n; ++k) uc.segment<2>(2 * k) = u.segment<2>(2 * dofs.node(c, k));
    sigma.col(c) = D_ * (strain_.block(c) * uc);
  }
  return sigma;
}

Eigen::Vector2d CrackInsertion::traction(const Eigen::Matrix3Xd& stresses, int e) const {
  const MeshEdge& edge = mesh_.edge(e);
  const Eigen::Vector3d s = 0.5 * (stresses.col(edge.cell0) + stresses.col(edge.cell1));
  const Eigen::Vector2d t = (mesh_.vertex(edge.v1) - mesh_.vertex(edge.v0)).normalized();
  const Eigen::Vector2d n(t.y(), -t.x());
  const Eigen::Vector2d sn(s[0] * n.x() + s[2] * n.y(), s[2] * n.x() + s[1] * n.y());
  return {sn.dot(n), sn.dot(t)};
}

std::vector<CrackInsertion::Failure> CrackInsertion::failing_edges(const SplitDofMap& dofs,
                                                                   const Eigen::VectorXd& u,
                                                                   const std::vector<char>& cracked,
                                                                   int threads) const {
  const Eigen::Matrix3Xd sigma = cell_stresses(dofs, u, threads);
  std::vector<Failure> failing;
  for (int e = 0; e < mesh_.num_edges(); ++e) {
    if (!eligible_[e] || cracked[e] || mesh_.edge(e).cell1 < 0) continue;
    const Eigen::Vector2d t = traction(sigma, e);
    if (criterion_.utilization(t[0], t[1]) >= 1.0) failing.push_back({e, t});
  }
  return failing;
}

}  // namespace vorodg
