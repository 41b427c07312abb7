#include "verification/harness/PhysicsKeys.hpp"

#include "core/element/ElementTable.hpp"
#include "verification/model/Choices.hpp"
#include "verification/model/SettingsSchema.hpp"

namespace vorodg {

std::vector<SceneKey> naming_keys() {
  return {key("name", "string", "file stem", "any", "the study's name in reports"),
          key("description", "string", "\"\"", "any", "one sentence for --list and the report")};
}

SceneKey meshes_key(const std::string& more) {
  return key("meshes[]", "list (required)", "", "as in every study (docs/scenes.md)",
             "mesh families with sizes, realizations, seed" + more);
}

SceneKey variants_key() {
  return key("variants[]", "objects with a label", "none", "",
             "each merged over the top-level keys; each runs into DIR/<label>/");
}

std::vector<SceneKey> elastic_keys(const std::string& E, const std::string& nu) {
  return {bounded("material.E", "number", E, "0 < E <= 1e13",
                  "Young's modulus, Pa (no solid is stiffer than about 1.2e12)", 0.0, true, 1e13),
          bounded("material.nu", "number", nu, "-1 < nu < 0.5", "Poisson's ratio", -1.0, true, 0.5,
                  true),
          key("material.plane", "string", "stress", "stress or strain", "plane stress or strain")};
}

std::vector<SceneKey> element_keys() {
  return {key("element", "string", element_name(ElementOptions{}.family),
              choice_list(element_choices()),
              "the element: its shape functions (docs/element.md, \"Which element for what\")"),
          bounded("vem_stabilization", "number", exact_text(ElementOptions{}.vem_stabilization),
                  "0 < tau <= 1e6",
                  "vem: the stabilization's scale tau, times trace(K_consistency) / (2n)", 0.0,
                  true, 1e6)};
}

std::vector<SceneKey> cohesive_keys(const CohesiveDefaults& d) {
  const std::string& s = d.scope;
  return {
      key("cohesive.law", "string", "linear", "linear or bilinear",
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
