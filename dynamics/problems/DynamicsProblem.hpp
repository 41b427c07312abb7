#pragma once
// One problem of explicit dynamics, as a class (the dynamics side's counterpart of the static
// ExactSolution): what it throws, strikes or stretches. Each problem owns its bodies' defaults,
// the scene keys only it reads with their rows (a wave bar's pulse, a projectile, a second
// block), its boundary conditions and initial velocities beyond the rigid motion, the length of
// a run when the scene gives none, the measures of its own (a wave's arrival) and the columns a
// report shows for it. It works on the plain parameters of a run (ExplicitParameters): a study's
// scene, the probe and the report ask the problem, and none of them names one. The problems are
// listed once, in DynamicsProblems.cpp.
#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/Rectangle.hpp"
#include "core/schema/SceneKeys.hpp"
#include "dynamics/CentralDifference.hpp"
#include "dynamics/ExplicitLoading.hpp"
#include "dynamics/ExplicitParameters.hpp"

namespace vorodg {

struct BodiesMesh;
class StateArchive;
struct DynamicsMeasures;
class SceneKeyReader;
class PolygonMesh;
struct MeshSpec;

/// Measures a problem takes beside the common ones (energy, momenta, contact, rotations).
class ProblemProbe {
 public:
  virtual ~ProblemProbe() = default;
  /// After every step.
  virtual void observe(DynamicsMeasures& m) = 0;
  /// Fragmentation: the run's cohesive faces (before the first step), for their closed-form
  /// energies.
  virtual void watch_cracks(const CohesiveForces&) {}
  /// After the run (complete or stopped): the problem's own per-run files under `out`.
  virtual void write(const std::filesystem::path& /*out*/, const std::string& /*run*/) const {}
  /// Saves or loads what it carries from step to step (a checkpoint); nothing by default.
  virtual void archive(StateArchive& /*a*/) {}
};

/// A column of report.md: its header and the text of a run's cell.
struct ReportColumn {
  std::string header;
  std::function<std::string(const DynamicsMeasures&)> cell;
};

/// The contact and cell damping a problem's scenes get where they do not say (the keys
/// contact.plastic, contact.quiescent_penetration, contact.friction, wall.friction,
/// bulk_viscosity.linear and .quadratic): off for most problems; column-impact's are the report's.
struct ContactDefaults {
  bool plastic = false;
  double quiescent_penetration = 0.0, friction = 0.0, wall_friction = 0.0;
  double bulk_linear = 0.0, bulk_quadratic = 0.0;
};

/// The physics of a run it adds (ExplicitLoading: crack sites, boundaries, initial velocities)
/// and what the study needs of it besides.
class DynamicsProblem : public ExplicitLoading {
 public:
  virtual ~DynamicsProblem() = default;
  /// The name a scene gives as `problem`.
  virtual std::string name() const = 0;

  // ---- the scene's keys
  /// The rows of the keys only this problem reads (name, type, default, range, doc), spliced
  /// into the key table of the kinds that run it.
  virtual std::vector<SceneKey> keys() const { return {}; }
  /// The top-level names of keys(): every other problem refuses them.
  std::vector<std::string> own_keys() const;
  /// True where the problem exists only with crack insertion (a fragmentation study).
  virtual bool needs_fragmentation() const { return false; }
  /// The (first) body where `domain`, `initial_velocity` and `angular_velocity` are not given.
  virtual Rectangle default_domain() const = 0;
  virtual Eigen::Vector2d default_velocity() const { return Eigen::Vector2d::Zero(); }
  virtual double default_angular_velocity() const { return 0.0; }
  virtual Eigen::Vector2d default_gravity() const { return Eigen::Vector2d::Zero(); }
  /// Reads the problem's own keys, once the material and the first body are read (a second
  /// body goes into physics.bodies).
  virtual void read(SceneKeyReader& reader, ExplicitParameters& physics) = 0;
  /// True where the body is thrown at a fixed rigid plane: the wall is required.
  virtual bool hits_wall() const { return false; }
  /// The wall where the scene's `wall` leaves its point or normal out: by default the plane
  /// through the body's leading point, facing its velocity.
  virtual DynamicsWall default_wall(const ExplicitParameters& physics) const;
  /// The run's length where the scene gives neither time.end nor time.steps: sets one of them.
  virtual void default_length(ExplicitParameters& physics) const = 0;
  /// That default in words, for the key table.
  virtual std::string default_length_doc() const = 0;
  virtual ContactDefaults default_contact() const { return {}; }
  /// True where `material.thickness` means something (a load in newtons): the others refuse it.
  virtual bool uses_thickness() const { return false; }

  // ---- the mesh
  /// The (first) body's mesh spec as the problem needs it (a notch tip made a vertex).
  virtual MeshSpec mesh_spec(const MeshSpec& spec) const;
  /// Throws InputError where the bodies' mesh cannot carry the problem (no edges along a crack
  /// line, no vertex at a load point).
  virtual void check_mesh(const PolygonMesh&) const {}
  // crack_sites (ExplicitLoading): where cracks may form and where they are at t = 0.

  // ---- the run
  /// True where a velocity is prescribed on part of the boundary (momentum enters there).
  virtual bool prescribes_velocity() const { return false; }
  // add_boundaries and add_initial_velocity (ExplicitLoading): prescribed velocities and loads,
  // and what the problem adds to a node's velocity at t = 0 beyond its body's rigid motion.

  // ---- what is measured and reported
  /// True where the bodies keep their angular momentum unless something outside acts.
  virtual bool measures_angular_momentum() const { return false; }
  /// The measures of its own, with their theory set in `m` at t = 0 (nullptr: none); a curve
  /// it draws takes a point every `output_every` steps.
  virtual std::unique_ptr<ProblemProbe> probe(const ExplicitParameters&, const BodiesMesh&,
                                              const CentralDifference&, int output_every,
                                              DynamicsMeasures& m) const;
  /// The columns of report.md after the common ones; by default the contact's.
  virtual std::vector<ReportColumn> report_columns() const;
};

/// True where something outside the bodies changes their momentum: a wall, a prescribed
/// velocity, gravity or damping.
bool external_momentum(const ExplicitParameters& physics, const DynamicsProblem& problem);

/// A new problem of each kind, in the order docs and messages list them.
std::vector<std::unique_ptr<DynamicsProblem>> dynamics_problems();
/// The problem called `name`, fresh (its own keys not read yet); nullptr for an unknown name.
std::unique_ptr<DynamicsProblem> make_dynamics_problem(const std::string& name);
/// "per problem: a x, b and c y, else z" of a default that depends on the problem: problems with
/// the same text grouped, the largest group of two or more as "else".
std::string per_problem_text(const std::function<std::string(const DynamicsProblem&)>& text,
                             const std::string& separator = ", ");
/// The extent of a rectangle along a unit direction: the length a 1D wave crosses.
double extent(const Rectangle& r, const Eigen::Vector2d& direction);
/// The rectangle's corners, counter-clockwise from its lower left.
std::array<Eigen::Vector2d, 4> corners(const Rectangle& r);
/// A measure in report.md: blank where it was not measured.
std::string measure_text(double x, int precision = 6);

}  // namespace vorodg
