#include "fracture/CrackState.hpp"

#include <cmath>
#include <string>

#include "core/util/Errors.hpp"

namespace vorodg {

CrackState::CrackState(const PolygonMesh& mesh, const std::vector<char>& cracked)
    : mesh_(&mesh), cracked_(mesh.num_edges(), 0) {
  if (static_cast<int>(cracked.size()) != mesh.num_edges())
    throw InputError("crack state: " + std::to_string(cracked.size()) +
                     " edge flags for a mesh of " + std::to_string(mesh.num_edges()) + " edges");
  for (int e = 0; e < mesh.num_edges(); ++e) {
    // Boundary flags are dropped so that two states differ only where the crack can be.
    cracked_[e] = (cracked[e] && !mesh.edge(e).on_boundary()) ? 1 : 0;
    num_cracked_ += cracked_[e];
  }
}

CrackState::CrackState(const PolygonMesh& mesh, const std::vector<char>& cracked,
                       const Eigen::VectorXd& openings)
    : CrackState(mesh, cracked) {
  if (openings.size() != mesh.num_edges())
    throw InputError("crack state: " + std::to_string(openings.size()) +
                     " openings for a mesh of " + std::to_string(mesh.num_edges()) + " edges");
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const double w = openings[e];
    if (!std::isfinite(w) || w < 0.0 || (w > 0.0 && !cracked_[e]))
      throw InputError("crack state: opening of edge " + std::to_string(e) + " = " +
                       std::to_string(w) + ": expected finite, >= 0, and 0 unless cracked");
  }
  openings_ = openings;
}

CrackState CrackState::from_dofs(const PolygonMesh& mesh, const SplitDofMap& dofs) {
  std::vector<char> cracked(mesh.num_edges(), 0);
  for (int e = 0; e < mesh.num_edges(); ++e)
    cracked[e] = (!mesh.edge(e).on_boundary() && !dofs.joins(mesh, e)) ? 1 : 0;
  return CrackState(mesh, cracked);
}

void CrackState::require_same_mesh(const CrackState& a, const CrackState& b) {
  if (a.mesh_ != b.mesh_)
    throw InputError("crack states: compared states belong to different meshes (" +
                     std::to_string(a.mesh_->num_edges()) + " and " +
                     std::to_string(b.mesh_->num_edges()) + " edges)");
}

int CrackState::hamming(const CrackState& a, const CrackState& b) {
  require_same_mesh(a, b);
  int differ = 0;
  for (std::size_t e = 0; e < a.cracked_.size(); ++e) differ += a.cracked_[e] != b.cracked_[e];
  return differ;
}

double CrackState::opening_distance(const CrackState& a, const CrackState& b) {
  require_same_mesh(a, b);
  if (!a.has_openings() || !b.has_openings())
    throw InputError("crack states: the opening distance needs openings on both states");
  const PolygonMesh& mesh = a.mesh();
  double weighted = 0.0, length = 0.0;
  for (int e = 0; e < mesh.num_edges(); ++e) {
    if (mesh.edge(e).on_boundary()) continue;
    const double l = mesh.edge_length(e);
    weighted += std::abs(a.openings_[e] - b.openings_[e]) * l;
    length += l;
  }
  return length > 0.0 ? weighted / length : 0.0;
}

}  // namespace vorodg
