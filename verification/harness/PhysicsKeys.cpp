#include "verification/harness/PhysicsKeys.hpp"

#include "core/element/ElementTable.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Format.hpp"
#include "verification/model/Choices.hpp"

namespace vorodg {

std::vector<SceneKey> naming_keys() {
  return {key("name", "string", "file stem", "any", "the study's name in reports"),
          key("description", "string", "\"\"", "any", "one sentence for --list and the report")};
}

std::vector<SceneKey> mesh_keys() {
  const MeshSpec spec;  // the generators' defaults
  const std::string families = "rcp, hex, perturbed-hex, tri, quad, file";
  return {
      key("meshes[]", "list (required)", "", "a non-empty list of mesh blocks",
          "one block per mesh family; each realization of each level is a run"),
      key("meshes[].family", "string", "rcp", families,
          "the mesh generator, or `file`: meshes read from `files`"),
      key("meshes[].label", "string", "the family", "any",
          "names the block in reports (two blocks of one family need labels)"),
      bounded("meshes[].sizes", "number or list (required, not with file)", "",
              "each > 0, at most the domain's longer side, coarse to fine",
              "d (rcp, tri) or h (hex, perturbed-hex, quad) of each level", 0.0, true,
              kCoordinateLimit),
      key("meshes[].files", "string or list (required with file)", "",
          "regular .vtu files, h_avg strictly decreasing",
          "one mesh per level, relative to the scene file's folder, each read and validated on "
          "the domain when the scene is read; its h_avg is the level's size"),
      bounded("meshes[].realizations", "integer", "1", "1 <= realizations <= 1e6 (file: 1)",
              "random meshes per level", 1.0, false, 1e6),
      bounded("meshes[].seed", "integer", std::to_string(spec.seed), "0 <= seed <= 2^53",
              "base seed; realization i of level l uses a pure function of (seed, l, i)", 0.0,
              false, 9007199254740992.0),
      bounded("meshes[].perturbation", "number", exact_text(spec.perturbation),
              "0 <= r < " + fmt(kMaxPerturbation),
              "perturbed-hex: the vertices' random shift, a fraction of h", 0.0, false,
              kMaxPerturbation, true),
      bounded("meshes[].regularization", "number", exact_text(spec.regularization),
              "0 <= x < " + fmt(kMaxRegularization), "rcp: edges shorter than x d are collapsed",
              0.0, false, kMaxRegularization, true),
      key("meshes[].symmetric", "bool or string", "false", "true, false or \"notch\" (rcp only)",
          "rcp: the whole mesh mirrored about the vertical mid-line, or (notch) along the notch "
          "and at the load point only"),
  };
}

const SceneKey& mesh_key(const std::string& name) {
  static const KeyTable table{"mesh", mesh_keys(), {}};
  return table.at(name);
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
      key("cohesive.law", "string", d.law_default, d.law_names,
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
