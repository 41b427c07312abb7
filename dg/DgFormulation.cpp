#include "dg/DgFormulation.hpp"

#include "core/util/NamedRegistry.hpp"
#include "dg/DgElasticity.hpp"

namespace vorodg {

// The shipped schemes, one file each under dg/formulations/.
std::unique_ptr<DgFormulation> make_penalty_only(const DgOptions& options);
std::unique_ptr<DgFormulation> make_augmented_lagrangian(const DgOptions& options);
std::unique_ptr<DgFormulation> make_iterative_nitsche(const DgOptions& options);
std::unique_ptr<DgFormulation> make_interior_penalty(const DgOptions& options);

namespace {

NamedRegistry<DgFormulationEntry>& registry() {
  static NamedRegistry<DgFormulationEntry> entries(
      "DG formulation",
      {
          {"dg-penalty", "DG, interior penalty only (inconsistent: fails the patch test)",
           make_penalty_only},
          {"dg-al", "DG, augmented Lagrangian: multipliers updated after each solve",
           make_augmented_lagrangian},
          {"dg-nitsche", "DG, iterative Nitsche with each cell's mean stress",
           make_iterative_nitsche},
          {"dg-sipg", "DG, symmetric interior penalty (one solve)", make_interior_penalty},
      });
  return entries;
}

}  // namespace

Eigen::MatrixXd DgTermContext::consistency_block(std::size_t i) const {
  return ops.consistency_block(space.interfaces()[i], traction, penalty.weights(i));
}

const std::vector<DgFormulationEntry>& dg_formulations() {
  return registry().entries();
}

bool register_dg_formulation(DgFormulationEntry entry) {
  return registry().add(std::move(entry));
}

std::unique_ptr<DgFormulation> make_dg_formulation(const DgOptions& options) {
  return registry().at(options.formulation).make(options);
}

}  // namespace vorodg
