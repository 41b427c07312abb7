#include "fracture/CohesiveKeys.hpp"

#include "fracture/SofteningLaws.hpp"

namespace vorodg {

std::vector<SceneKey> cohesive_keys(const CohesiveDefaults& d) {
  const std::string& s = d.scope;
  return {
      key("cohesive.law", "string", softening_laws().front().name, softening_law_list(),
          s + "the softening of the cohesive law: linear, or bilinear with the kink at "
              "sigma_c / 3 (docs/fracture.md)"),
      bounded("cohesive.strength", "number", d.strength, "0 < sigma_c <= 1e11",
              s + "sigma_c, the law's peak traction, Pa", 0.0, true, 1e11),
      bounded("cohesive.fracture_energy", "number", d.fracture_energy, "0 < G <= 1e7",
              s + "G, the area under the law, J/m^2", 0.0, true, 1e7),
      bounded("cohesive.shear_factor", "number", "1", "0 <= beta <= 1000",
              s + "beta: the effective opening is sqrt(dn^2 + beta^2 dt^2)", 0.0, false, 1e3),
      bounded("cohesive.initial_stiffness", "number", d.initial_stiffness, "0 < K0 <= 1e9",
              s + "K0 in units of E / h_avg (" + d.initial_stiffness_use + ")", 0.0, true, 1e9),
      bounded("criterion.cohesion", "number", "cohesive.strength", "0 < c <= 1e11",
              s + "the Mohr-Coulomb cohesion c of the insertion criterion, Pa", 0.0, true, 1e11),
      bounded("criterion.friction", "number", d.friction, "0 <= mu <= 1000",
              s + "the Mohr-Coulomb friction coefficient mu", 0.0, false, 1e3),
      bounded("criterion.tensile_cutoff", "number", "cohesive.strength", "0 < sigma_o <= 1e11",
              s + "the criterion's tensile cutoff sigma_o, Pa", 0.0, true, 1e11)};
}

}  // namespace vorodg
