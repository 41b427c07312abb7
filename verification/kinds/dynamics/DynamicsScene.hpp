#pragma once
// The scene of a `dynamics` study (keys in docs/dynamics.md "The dynamics study"): one problem
// (a wave bar, a free body, a block thrown at a rigid wall, two blocks thrown at each other), one
// material, contact, the time stepping, over mesh families with levels and realizations. A
// `fragmentation` study is the same with cracks (docs/fragmentation.md): the cohesive law and the
// insertion criterion, and the strip-expansion problem. The impact problems of the report (a
// column falling onto an inclined rigid plane, a beam struck by a rigid projectile) may run in
// either study kind (their keys in ImpactKeys.cpp).
// `variants` (objects merged over the top-level keys, each with a `label`) runs several such
// studies side by side, each into its own subfolder.
//
// Every key's name, type, default, range and doc are in one table (dynamics_scene_keys, in
// DynamicsKeys.cpp); the reader takes defaults and ranges from it, refuses what is out of range
// with one line naming the key, and records every value it used (`settings`) for the echo.
#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/element/ElementTable.hpp"
#include "core/geometry/Rectangle.hpp"
#include "core/material/CohesiveLaw.hpp"
#include "core/material/IsotropicElasticity.hpp"
#include "core/material/MohrCoulomb.hpp"
#include "dynamics/contact/PenaltyContact.hpp"
#include "verification/study/Scene.hpp"

namespace vorodg {

enum class DynamicsProblem {
  wave_bar,
  free_body,
  wall_impact,
  two_blocks,
  strip_expansion,
  column_impact,
  projectile_impact
};
enum class StepEstimate { lanczos, cells };

std::string dynamics_problem_name(DynamicsProblem p);
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
};

/// A rigid flat-nosed projectile of infinite mass moving down at constant speed onto the top side
/// of the body: the vertical velocity of the top vertices under its nose is prescribed from t = 0
/// (bonded in the normal direction, free to slide).
struct DynamicsProjectile {
  double speed = 0.0;     // m/s, downwards
  double width = 0.0;     // of the nose, m
  double position = 0.0;  // x of the nose's centre, m
};

struct DynamicsScene {
  std::filesystem::path path;
  std::string name, description, label;  // label: the variant's (empty at the top level)
  DynamicsProblem problem = DynamicsProblem::wave_bar;
  std::vector<DynamicsBody> bodies;  // one; two-blocks: two
  double E = 0.0, nu = 0.0, density = 0.0;
  PlaneModel plane = PlaneModel::stress;
  bool mean_dilation = false;
  ElementOptions element;            // `element`, `vem_stabilization`: the element family
  bool corotational = false;         // kinematics: small strain in turning cell frames
  double variation = 0.0;            // per-cell factors on E and strength in [1 - x, 1 + x]
  std::uint64_t variation_seed = 1;  // their stream (MaterialVariation)
  double damping = 0.0;              // mass-proportional, 1/s
  Eigen::Vector2d gravity = Eigen::Vector2d::Zero();  // body force per unit mass, m/s^2
  // wave-bar
  bool rollers = false;  // sides: rollers on the long sides (uniaxial strain)
  double pulse_amplitude = 0.0, pulse_duration = 0.0;
  // contact
  std::optional<DynamicsWall> wall;
  double obliquity = 0.0;  // column-impact: the plane's tilt, degrees
  std::optional<DynamicsProjectile> projectile;
  bool contact = true;  // surface-to-surface contact
  PenaltyParameters penalty;
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
  double strain_rate = 0.0;  // strip-expansion
  CohesiveParameters cohesive;
  double stiffness_factor = 0.0;  // K0 in units of E / h_avg
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
  /// wave-bar: the speed the pulse should travel at (dilatational with rollers, else bar).
  double wave_speed() const;
  /// True where the body hits a fixed rigid plane (wall-impact, column-impact).
  bool hits_wall() const;
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
