#pragma once
// The scene of a `fracture` study (keys in FractureKeys.cpp, listed in docs/scenes.md "Fracture
// studies"): one problem, one
// material, one cohesive law and criterion, one cracking mode and loading, over mesh families with
// levels and realizations. `variants` (a list of objects merged over the top-level keys, each
// with a `label`) runs several such studies side by side, each into its own subfolder.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/element/ElementTable.hpp"
#include "core/material/IsotropicElasticity.hpp"
#include "core/random/MaterialField.hpp"
#include "dg/QuasiStaticPath.hpp"
#include "fracture/CohesiveLaw.hpp"
#include "fracture/FractureProblem.hpp"
#include "fracture/MohrCoulomb.hpp"
#include "verification/harness/MeshBlock.hpp"
#include "verification/harness/RunCheckpoints.hpp"
#include "verification/harness/StatisticalReport.hpp"

namespace vorodg {

struct FractureScene {
  std::filesystem::path path;
  std::string name, description, label;  // label: the variant's (empty at the top level)
  FractureGeometry geometry;
  double E = 30e9, nu = 0.2;
  PlaneModel plane = PlaneModel::stress;
  double thickness = 1.0;
  /// A random field of strength (docs/statistics.md): the crack faces' law and criterion scale
  /// by it, face by face; the bulk's stiffness stays uniform.
  MaterialField field;
  CohesiveParameters law;           // initial_stiffness set per mesh for pre-inserted faces
  MohrCoulombParameters criterion;  // cohesion, friction, tensile cutoff (default: strength)
  double initial_stiffness = 1e3;   // pre-inserted: K0 = this x E / h_avg
  ElementOptions element;           // `element`, `vem_stabilization`: the element family
  CrackingMode mode = CrackingMode::restricted;
  bool split_all = false;  // cracking.split_all: the full DG space whatever the mode
  PathOptions loading;
  std::vector<SceneMesh> meshes;
  int vtu_every = 10;  // a .vtu of the deformed mesh every this many steps (0: none)
  /// How often a path checkpoints (not part of what a checkpoint must match).
  CheckpointPolicy checkpoint;
  /// The quantities whose convergence over the mesh levels the report judges (`statistics`).
  StatisticalSettings statistics;
  /// Every key and the value used, in the key table's order (the echo).
  std::vector<std::pair<std::string, std::string>> settings;
  std::vector<FractureScene> variants;
};

/// Reads a fracture scene from its JSON text; throws InputError naming the key.
FractureScene parse_fracture_scene(const std::string& text, const std::string& source);
FractureScene read_fracture_scene(const std::filesystem::path& path);

}  // namespace vorodg
