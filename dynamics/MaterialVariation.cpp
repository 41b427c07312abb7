#include "dynamics/MaterialVariation.hpp"

#include <cmath>

#include "core/util/Errors.hpp"
#include "core/util/Random.hpp"

namespace vorodg {

MaterialVariation MaterialVariation::uniform(int cells, double amount, std::uint64_t seed) {
  if (!std::isfinite(amount) || amount < 0.0 || amount >= 1.0)
    throw InputError("material variation: expected 0 <= x < 1, found " + std::to_string(amount));
  MaterialVariation v;
  if (amount == 0.0) return v;
  v.stiffness.resize(cells), v.strength.resize(cells);
  for (int c = 0; c < cells; ++c) {
    Random random(derive_seed(seed, static_cast<std::uint64_t>(c)));
    v.stiffness[c] = random.uniform(1.0 - amount, 1.0 + amount);
    v.strength[c] = random.uniform(1.0 - amount, 1.0 + amount);
  }
  return v;
}

std::vector<double> MaterialVariation::edge_strength(const PolygonMesh& mesh) const {
  if (empty()) return {};
  std::vector<double> f(mesh.num_edges());
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const MeshEdge& edge = mesh.edge(e);
    f[e] =
        edge.cell1 < 0 ? strength[edge.cell0] : 0.5 * (strength[edge.cell0] + strength[edge.cell1]);
  }
  return f;
}

}  // namespace vorodg
