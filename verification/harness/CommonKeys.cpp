#include "verification/harness/CommonKeys.hpp"

#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Format.hpp"

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
      key("meshes[].realizations_per_level", "list of integers", "none",
          "one per size, each 1..1e6; not beside realizations",
          "random meshes of each level instead of one count for all (a statistical campaign: "
          "many coarse runs, few fine ones)"),
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

std::vector<SceneKey> checkpoint_keys() {
  return {
      bounded("checkpoint.wall_seconds", "number", "60", "0 <= wall_seconds <= 1e9",
              "wall seconds between a run's checkpoints (checkpoints/<run>.ckpt, the one before "
              "kept as .prev; removed when the run finishes); a rerun into the same folder "
              "continues each unfinished run from its last one; 0: none by time "
              "(docs/checkpoints.md)",
              0.0, false, 1e9),
      bounded("checkpoint.steps", "integer", "0", "0 <= steps <= 1e9",
              "also a checkpoint every this many steps; 0: by wall time only", 0.0, false, 1e9),
  };
}

}  // namespace vorodg
