#include "dynamics/LumpedMass.hpp"

#include <string>

#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"

namespace vorodg {

LumpedMass::LumpedMass(const ElementTable& table, double density)
    : offsets_(table.mesh().offsets()), density_(density) {
  require_parameter(density > 0.0, "density", density, "> 0");
  if (!table.has_shape_values())
    throw NumericalError("internal: lumped masses from an element table built without psi");
  const PolygonMesh& mesh = table.mesh();
  pair_.assign(offsets_.back(), 0.0);
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const int n = table.num_nodes(c);
    double* row = pair_.data() + offsets_[c];
    for (int q = 0; q < table.num_points(c); ++q)
      for (int k = 0; k < n; ++k) row[k] += table.weight(c, q) * table.shape(c, q, k);
    for (int k = 0; k < n; ++k) {
      row[k] *= density;
      if (!(row[k] > 0.0))
        throw NumericalError("lumped mass: cell " + std::to_string(c) + ", vertex " +
                             std::to_string(mesh.cell_vertices(c)[k]) + " (local " +
                             std::to_string(k) + "): expected a positive row-sum mass, found " +
                             fmt(row[k]));
      total_ += row[k];
    }
  }
}

Eigen::VectorXd LumpedMass::node_masses(const SplitDofMap& dofs) const {
  Eigen::VectorXd m(dofs.num_nodes());
  for (int i = 0; i < dofs.num_nodes(); ++i) m[i] = node_mass(dofs, i);
  return m;
}

double LumpedMass::node_mass(const SplitDofMap& dofs, int i) const {
  double m = 0.0;
  for (int p : dofs.node_pairs(i)) m += pair_[p];
  return m;
}

}  // namespace vorodg
