#pragma once
// The scene of a `dynamics` study (keys in docs/scenes.md): one problem (a class of problems/: a
// wave bar, a free body, a block thrown at a rigid wall, two blocks thrown at each other, the
// report's falling column and struck beam), one material, contact, the time stepping, over mesh
// families with levels and realizations. A `fragmentation` study is the same with cracks
// (docs/fragmentation.md): the cohesive law and the insertion criterion, and the strip-expansion
// problem.
// `variants` (objects merged over the top-level keys, each with a `label`) runs several such
// studies side by side, each into its own subfolder.
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

#include "core/element/ElementTable.hpp"
#include "core/geometry/Rectangle.hpp"
#include "core/material/CohesiveLaw.hpp"
#include "core/material/IsotropicElasticity.hpp"
#include "core/material/MohrCoulomb.hpp"
#include "dynamics/BulkViscosity.hpp"
#include "dynamics/contact/PenaltyContact.hpp"
#include "verification/kinds/dynamics/problems/DynamicsProblem.hpp"
#include "verification/study/Scene.hpp"

namespace vorodg {

enum class StepEstimate { lanczos, cells };

std::string step_estimate_name(StepEstimate e);

/// A rectangular body and how it is thrown: a uniform velocity plus a spin about its centre of
/// mass.
struct DynamicsBody {
  Rectangle domain;
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();
  double angular_velocity = 0.0;
};

struct DynamicsWall {
  Point point = Point::Zero();
  Point normal = Point(-1.0, 0.0);  // into free space; normalized by the reader
  double friction = 0.0;            // Coulomb's mu between the plane and the bodies
};

struct DynamicsScene {
  std::filesystem::path path;
  std::string name, description, label;  // label: the variant's (empty at the top level)
  /// What is thrown, struck or stretched, with its own keys read (problems/).
  std::shared_ptr<const DynamicsProblem> problem;
  std::vector<DynamicsBody> bodies;  // one; two-blocks: two
  double E = 0.0, nu = 0.0, density = 0.0;
  PlaneModel plane = PlaneModel::stress;
  double thickness = 1.0;  // out of plane, m: only problems whose loads are in newtons read it
  bool mean_dilation = false;
  ElementOptions element;            // `element`, `vem_stabilization`: the element family
  bool corotational = false;         // kinematics: small strain in turning cell frames
  bool dg_interfaces = false;        // interfaces: every interior edge split and coupled from t = 0
  double variation = 0.0;            // per-cell factors on E and strength in [1 - x, 1 + x]
  std::uint64_t variation_seed = 1;  // their stream (MaterialVariation)
  double damping = 0.0;              // mass-proportional, 1/s
  BulkViscosityParameters bulk_viscosity;             // b1, b2 on the cells (off by default)
  Eigen::Vector2d gravity = Eigen::Vector2d::Zero();  // body force per unit mass, m/s^2
  // contact
  std::optional<DynamicsWall> wall;
  bool contact = true;  // surface-to-surface contact
  PenaltyParameters penalty;
  double contact_friction = 0.0;  // Coulomb's mu between surface cells
  /// > 0: the displacement penalty follows from it instead of alpha: the bodies resting under
  /// gravity on the wall sink by at most this fraction of h_avg (DynamicsModel).
  double quiescent_penetration = 0.0;
  // time
  double end = 0.0;  // 0: `steps` sets the length
  int steps = 0;     // 0: `end` sets it
  double safety = 0.0;
  StepEstimate estimate = StepEstimate::lanczos;
  int output_every = 0, history_every = 0;
  bool vtu = true;
  std::vector<double> snapshots;  // times of extra frames (ascending), s
  // fragmentation (study kind): crack insertion with the cohesive law on every interior edge
  bool fragmentation = false;
  CohesiveParameters cohesive;
  double stiffness_factor = 0.0;   // K0 in units of E / h_avg
  double face_friction = 0.0;      // Coulomb's mu on closed crack faces
  double closure_fraction = 0.1;   // the faces' overclosure penalty, of K0
  bool interface_closure = false;  // interfaces dg: each face's overclosure is its penalty eps
  bool turning_faces = false;      // corotational: faces read openings in turning frames
  MohrCoulombParameters criterion;
  std::vector<SceneMesh> meshes;
  /// Every key and the value used, in the table's order (the echo and summary.json).
  std::vector<std::pair<std::string, std::string>> settings;
  std::vector<DynamicsScene> variants;
  /// perturb (top level only): the key its variants change and each variant's value (JSON).
  std::string perturb_key;
  std::vector<std::string> perturb_values;

  /// The speeds of the material: uniaxial stress (bar) and uniaxial strain (dilatational).
  double bar_speed() const;
  double dilatational_speed() const;
  /// The value used for `key`, as echoed; throws std::out_of_range for a key not read.
  const std::string& setting(const std::string& key) const;
  /// True where something outside the bodies changes their momentum: a wall, a prescribed
  /// velocity, gravity or damping.
  bool external_momentum() const;
};

/// Reads a dynamics scene from its JSON text; throws InputError naming the key. `force` allows
/// time.safety >= 1 (`vorodg run --force`).
DynamicsScene parse_dynamics_scene(const std::string& text, const std::string& source,
                                   bool force = false);
DynamicsScene read_dynamics_scene(const std::filesystem::path& path, bool force = false);

}  // namespace vorodg
