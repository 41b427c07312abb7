#include "core/random/MaterialVariation.hpp"

#include <cmath>

#include "core/random/CirculantEmbedding.hpp"
#include "core/random/GaussianRandomField.hpp"
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

MaterialVariation MaterialVariation::from_field(const PolygonMesh& mesh, const MaterialField& field,
                                                int realization) {
  MaterialVariation v;
  if (!field.enabled) return v;
  field.marginal.check();
  const CirculantEmbedding embedding(mesh.domain(), field.covariance, field.spacing);
  const auto cell_means = [&](int which) {
    const GaussianRandomField g(embedding, field.field_seed(realization, which));
    std::vector<double> factor(mesh.num_cells());
    for (int c = 0; c < mesh.num_cells(); ++c)
      factor[c] = g.mean_over(mesh.cell_points(c), [&](double x) { return field.marginal(x); });
    return factor;
  };
  const bool strength_only = field.marginal.kind == MarginalKind::weibull;
  v.stiffness = strength_only ? std::vector<double>(mesh.num_cells(), 1.0) : cell_means(0);
  v.strength = cell_means(1);
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
