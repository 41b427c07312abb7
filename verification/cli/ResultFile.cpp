#include "verification/cli/ResultFile.hpp"

namespace vorodg {
namespace {

/// Per-cell result fields (mean stress, von Mises, error densities, largest interface gap).
std::vector<VtuField> cell_fields(const PolygonMesh& mesh, const SolveResult& r,
                                  const ExactSolution& exact) {
  VtuField stress{"mean_stress", 3, {}}, vm{"von_mises", 1, {}}, id{"cell_id", 1, {}};
  VtuField gap{"max_interface_gap", 1, {}};
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const Eigen::Vector3d& s = r.cell_mean_stress[c];
    stress.values.insert(stress.values.end(), {s[0], s[1], s[2]});
    vm.values.push_back(exact.material().von_mises(s));
    id.values.push_back(c);
    double largest = 0.0;
    for (int e : mesh.cell_edges(c)) largest = std::max(largest, r.edge_gaps[e]);
    gap.values.push_back(largest);
  }
  if (!r.errors_measured) return {stress, vm, id, gap};
  return {stress,
          vm,
          {"l2_error_density", 1, r.cell_l2_density},
          {"energy_error_density", 1, r.cell_energy_density},
          id,
          gap};
}

/// Displacement, exact displacement and error at the given points (3 components, z = 0).
std::vector<VtuField> point_fields(const std::vector<Point>& points, const Eigen::Matrix2Xd& uh,
                                   const ExactSolution& exact) {
  VtuField u{"displacement", 3, {}}, ue{"exact_displacement", 3, {}}, err{"error", 3, {}};
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d h = uh.col(i), x = exact.displacement(points[i]);
    u.values.insert(u.values.end(), {h.x(), h.y(), 0.0});
    ue.values.insert(ue.values.end(), {x.x(), x.y(), 0.0});
    err.values.insert(err.values.end(), {h.x() - x.x(), h.y() - x.y(), 0.0});
  }
  return {u, ue, err};
}

}  // namespace

void write_result(const std::string& path, const PolygonMesh& mesh, const SolveResult& r,
                  const ExactSolution& exact, bool discontinuous, VtuEncoding encoding) {
  if (!discontinuous) {
    write_vtu(
        path, mesh,
        {point_fields(mesh.vertices(), r.vertex_displacement, exact), cell_fields(mesh, r, exact)},
        encoding);
    return;
  }
  std::vector<Point> points;
  std::vector<int> offsets{0}, cells;
  Eigen::Matrix2Xd uh(2, r.cell_dof_values.size() / 2);
  for (int c = 0; c < mesh.num_cells(); ++c)
    for (int k = 0; k < mesh.cell_size(c); ++k) {
      const int copy = static_cast<int>(points.size());
      points.push_back(mesh.vertex(mesh.cell_vertices(c)[k]));
      uh.col(copy) = r.cell_dof_values.segment<2>(r.cell_offsets[c] + 2 * k);
      cells.push_back(copy);
      if (k + 1 == mesh.cell_size(c)) offsets.push_back(static_cast<int>(cells.size()));
    }
  const PolygonMesh exploded(mesh.domain(), points, offsets, cells);
  write_vtu(path, exploded, {point_fields(points, uh, exact), cell_fields(mesh, r, exact)},
            encoding);
}

}  // namespace vorodg
