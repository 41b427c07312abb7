#pragma once
// Everything an explicit run of the bodies needs beyond their mesh and the problem's loads
// (ExplicitLoading), as plain values: the material and element, the kinematics, damping and bulk
// viscosity, gravity, contact (surfaces, a wall and its law, the penalty), the time stepping and,
// for a fragmentation run, the cohesive law and the insertion criterion. ExplicitModel builds a
// run from it. A study's scene is these values plus what the study adds (its meshes, outputs and
// records); a library user fills them directly.
#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/element/ElementTable.hpp"
#include "core/geometry/Rectangle.hpp"
#include "core/material/IsotropicElasticity.hpp"
#include "core/random/MaterialField.hpp"
#include "dynamics/BulkViscosity.hpp"
#include "dynamics/contact/ContactLaws.hpp"
#include "dynamics/contact/PenaltyContact.hpp"
#include "fracture/CohesiveLaw.hpp"
#include "fracture/MohrCoulomb.hpp"

namespace vorodg {

/// Which estimate of the critical step the step is a fraction of.
enum class StepEstimate { lanczos, cells };

std::string step_estimate_name(StepEstimate e);

/// A rectangular body and how it is thrown: a uniform velocity plus a spin about its centre of
/// mass.
struct DynamicsBody {
  Rectangle domain;
  Eigen::Vector2d velocity = Eigen::Vector2d::Zero();
  double angular_velocity = 0.0;
};

/// A fixed rigid plane the bodies meet.
struct DynamicsWall {
  Point point = Point::Zero();
  Point normal = Point(-1.0, 0.0);              // into free space; normalized by the reader
  double friction = 0.0;                        // Coulomb's mu between the plane and the bodies
  std::string law = default_contact_law(true);  // how it acts: an obstacle law (ContactLaws)
};

struct ExplicitParameters {
  std::vector<DynamicsBody> bodies;  // one; two-blocks: two
  // the material and the element
  double E = 0.0, nu = 0.0, density = 0.0;
  PlaneModel plane = PlaneModel::stress;
  double thickness = 1.0;  // out of plane, m: only problems whose loads are in newtons read it
  bool mean_dilation = false;
  ElementOptions element;                  // the element family and its options
  bool corotational = false;               // kinematics: small strain in turning cell frames
  bool dg_interfaces = false;              // every interior edge split and coupled from t = 0
  double variation = 0.0;                  // per-cell factors on E and strength in [1 - x, 1 + x]
  std::uint64_t variation_seed = 1;        // their stream (MaterialVariation), with the run's seed
  MaterialField field;                     // or factors from a random field in space
  double damping = 0.0;                    // mass-proportional, 1/s
  BulkViscosityParameters bulk_viscosity;  // b1, b2 on the cells (off by default)
  Eigen::Vector2d gravity = Eigen::Vector2d::Zero();  // body force per unit mass, m/s^2
  // contact
  std::optional<DynamicsWall> wall;
  bool contact = true;                                   // surface-to-surface contact
  std::string contact_law = default_contact_law(false);  // its law (ContactLaws)
  PenaltyParameters penalty;                             // of the penalty laws (and of none else)
  double contact_friction = 0.0;                         // Coulomb's mu between surface cells
  /// > 0: the displacement penalty follows from it instead of alpha: the bodies resting under
  /// gravity on the wall sink by at most this fraction of h_avg (ExplicitModel).
  double quiescent_penetration = 0.0;
  // time
  double end = 0.0;  // 0: `steps` sets the length
  int steps = 0;     // 0: `end` sets it
  double safety = 0.0;
  StepEstimate estimate = StepEstimate::lanczos;
  // fragmentation: crack insertion with the cohesive law on every edge that may crack
  bool fragmentation = false;
  CohesiveParameters cohesive;
  double stiffness_factor = 0.0;   // K0 in units of E / h_avg
  double face_friction = 0.0;      // Coulomb's mu on closed crack faces
  double closure_fraction = 0.1;   // the faces' overclosure penalty, of K0
  bool interface_closure = false;  // interfaces coupled: each face's overclosure is its penalty eps
  bool turning_faces = false;      // corotational: faces read openings in turning frames
  MohrCoulombParameters criterion;

  /// The speeds of the material: uniaxial stress (bar) and uniaxial strain (dilatational).
  double bar_speed() const;
  double dilatational_speed() const;
};

}  // namespace vorodg
