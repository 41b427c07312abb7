#include "dynamics/contact/PairState.hpp"

#include <string>

#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

void check_size(std::size_t found, int pairs, const char* field, const char* what) {
  if (static_cast<long long>(found) != pairs)
    throw InputError(std::string(what) + ": " + field + " has " + std::to_string(found) +
                     " entries: expected one per (cell, vertex) pair, " + std::to_string(pairs));
}

}  // namespace

void check_pair_state(const PolygonMesh& mesh, const PairState& state, const char* what) {
  const int pairs = mesh.offsets().back();
  check_size(state.position.size(), pairs, "position", what);
  if (!state.velocity.empty()) check_size(state.velocity.size(), pairs, "velocity", what);
  if (!state.mass.empty()) check_size(state.mass.size(), pairs, "mass", what);
  if (!state.node.empty()) check_size(state.node.size(), pairs, "node", what);
}

std::vector<Point> pair_positions(const PolygonMesh& mesh, const SplitDofMap& dofs,
                                  const Eigen::VectorXd& u) {
  std::vector<Point> x = pair_vectors(mesh, dofs, u);
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto loop = mesh.cell_vertices(c);
    for (std::size_t k = 0; k < loop.size(); ++k) x[mesh.offsets()[c] + k] += mesh.vertex(loop[k]);
  }
  return x;
}

std::vector<Point> pair_vectors(const PolygonMesh& mesh, const SplitDofMap& dofs,
                                const Eigen::VectorXd& nodal) {
  if (nodal.size() != dofs.num_dofs())
    throw InputError("contact: nodal vector has " + std::to_string(nodal.size()) +
                     " entries: expected " + std::to_string(dofs.num_dofs()));
  std::vector<Point> out(mesh.offsets().back());
  for (int c = 0; c < mesh.num_cells(); ++c)
    for (int k = 0; k < mesh.cell_size(c); ++k) {
      const int n = dofs.node(c, k);
      out[mesh.offsets()[c] + k] = Point(nodal[2 * n], nodal[2 * n + 1]);
    }
  return out;
}

std::vector<double> pair_scalars(const PolygonMesh& mesh, const SplitDofMap& dofs,
                                 const Eigen::VectorXd& nodal) {
  if (nodal.size() != dofs.num_nodes())
    throw InputError("contact: nodal scalar has " + std::to_string(nodal.size()) +
                     " entries: expected " + std::to_string(dofs.num_nodes()));
  std::vector<double> out(mesh.offsets().back());
  for (int c = 0; c < mesh.num_cells(); ++c)
    for (int k = 0; k < mesh.cell_size(c); ++k) out[mesh.offsets()[c] + k] = nodal[dofs.node(c, k)];
  return out;
}

std::vector<int> pair_nodes(const PolygonMesh& mesh, const SplitDofMap& dofs) {
  std::vector<int> out(mesh.offsets().back());
  for (int c = 0; c < mesh.num_cells(); ++c)
    for (int k = 0; k < mesh.cell_size(c); ++k) out[mesh.offsets()[c] + k] = dofs.node(c, k);
  return out;
}

void add_pair_forces(const PolygonMesh& mesh, const SplitDofMap& dofs, std::span<const Point> force,
                     Eigen::VectorXd& f) {
  if (f.size() != dofs.num_dofs())
    throw InputError("contact: force vector has " + std::to_string(f.size()) +
                     " entries: expected " + std::to_string(dofs.num_dofs()));
  check_size(force.size(), mesh.offsets().back(), "pair force", "contact");
  // Cell by cell, vertex by vertex: a fixed order, so the sums are bit-for-bit reproducible.
  for (int c = 0; c < mesh.num_cells(); ++c)
    for (int k = 0; k < mesh.cell_size(c); ++k) {
      const Point& fp = force[mesh.offsets()[c] + k];
      const int n = dofs.node(c, k);
      f[2 * n] += fp.x();
      f[2 * n + 1] += fp.y();
    }
}

}  // namespace vorodg
