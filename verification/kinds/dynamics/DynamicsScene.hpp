#pragma once
// The scene of a `dynamics` study (keys in docs/scenes.md): one problem (a class of
// dynamics/problems/: a wave bar, a free body, a block thrown at a rigid wall, two blocks thrown at
// each other, the report's falling column and struck beam), one material, contact, the time
// stepping, over mesh families with levels and realizations. A `fragmentation` study is the same
// with cracks (docs/fragmentation.md): the cohesive law and the insertion criterion, and the
// strip-expansion problem. `variants` (objects merged over the top-level keys, each with a `label`)
// runs several such studies side by side, each into its own subfolder.
//
// Every key's name, type, default, range and doc are in one table (dynamics_scene_keys, in
// DynamicsKeys.cpp); the reader takes defaults and ranges from it, refuses what is out of range
// with one line naming the key, and records every value it used (`settings`) for the echo.
#include <Eigen/Core>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dynamics/ExplicitParameters.hpp"
#include "dynamics/problems/DynamicsProblem.hpp"
#include "verification/harness/MeshBlock.hpp"
#include "verification/harness/RunCheckpoints.hpp"
#include "verification/harness/StatisticalReport.hpp"

namespace vorodg {

/// The physics (ExplicitParameters: bodies, material, contact, time, fracture) and what the study
/// adds: its name, problem, outputs, meshes, the echo of its keys and its variants.
struct DynamicsScene : ExplicitParameters {
  std::filesystem::path path;
  std::string name, description, label;  // label: the variant's (empty at the top level)
  /// What is thrown, struck or stretched, with its own keys read (dynamics/problems/).
  std::shared_ptr<const DynamicsProblem> problem;
  int output_every = 0, history_every = 0;
  bool vtu = true;
  /// How often a run checkpoints. Not part of what a checkpoint must match: a rerun may change it.
  CheckpointPolicy checkpoint;
  /// The quantities whose convergence over the mesh levels the report judges (`statistics`).
  StatisticalSettings statistics;
  std::vector<double> snapshots;  // times of extra frames (ascending), s
  std::vector<SceneMesh> meshes;
  /// Every key and the value used, in the table's order (the echo and summary.json).
  std::vector<std::pair<std::string, std::string>> settings;
  std::vector<DynamicsScene> variants;
  /// time.refinement: the fractions of the step each part runs at (empty: none), and the
  /// fraction this part runs at (its safety already holds it).
  std::vector<double> refinement;
  double step_fraction = 1.0;
  std::string refinement_base;  // a refined part: the label of the part it refines
  /// perturb (top level only): the key its variants change and each variant's value (JSON).
  std::string perturb_key;
  std::vector<std::string> perturb_values;

  /// The value used for `key`, as echoed; throws std::out_of_range for a key not read.
  const std::string& setting(const std::string& key) const;
};

/// Reads a dynamics scene from its JSON text; throws InputError naming the key. `force` allows
/// time.safety >= 1 (`vorodg run --force`).
DynamicsScene parse_dynamics_scene(const std::string& text, const std::string& source,
                                   bool force = false);
DynamicsScene read_dynamics_scene(const std::filesystem::path& path, bool force = false);

}  // namespace vorodg
