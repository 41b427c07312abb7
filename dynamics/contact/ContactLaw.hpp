#pragma once
// One way the mesh meets something: surface cells against surface cells (SurfaceContact), or
// against an obstacle outside the mesh (RigidPlane). ContactForces holds a list of them, gathers
// the surface pairs' state once per evaluation, lets each add its forces per (cell, vertex)
// pair, and books their work; it knows no law by name. A new law is one file with its class and
// a factory, plus one line in ContactLaws.cpp's table (or register_contact_law from anywhere, as
// a test does), and a scene chooses it by name (`wall.law` for an obstacle).
//
// What a law must keep for the energy account to close (ContactWork books the trapezoid work of
// whatever forces it adds): forces per pair in `force`, the velocity-dependent part of them in
// `velocity_force` too when that span is not empty, and the pairs it pushed in touched().
//
// A kinematic law (kinematic() true) adds no force of the current configuration: it enforces its
// constraint on the predicted next one by impulses (KinematicState), once every other force of
// the step is known; ContactForces books those impulses' work as forces of the step.
#include <span>
#include <string>
#include <vector>

#include "core/util/Errors.hpp"
#include "dynamics/contact/ContactReport.hpp"
#include "dynamics/contact/KinematicState.hpp"
#include "dynamics/contact/PairState.hpp"
#include "dynamics/contact/SurfaceCells.hpp"

namespace vorodg {

class StateArchive;

class ContactLaw {
 public:
  virtual ~ContactLaw() = default;

  /// True for an obstacle outside the mesh, which takes the reaction: its forces are external,
  /// reported apart (ContactForces::plane_report, plane_force). False for contact between parts
  /// of the mesh, whose forces are equal and opposite and move no momentum.
  virtual bool external() const = 0;
  /// Adds the law's forces on the surface cells' pairs at `state` to `force` (one entry per
  /// pair, the mesh's CSR layout) and their velocity-dependent part to `velocity_force` if it is
  /// not empty; reports the evaluation. Throws InputError if the state lacks what the law needs.
  virtual ContactReport add_forces(const SurfaceCells& surface, const PairState& state,
                                   std::span<Point> force, std::span<Point> velocity_force) = 0;
  /// The pairs the last add_forces gave a force (repeats allowed).
  virtual std::span<const int> touched() const = 0;
  /// True for a law enforced exactly by impulses (constrain), false for a force law.
  virtual bool kinematic() const { return false; }
  /// A kinematic law: applies the impulses that keep the surface cells' predicted positions
  /// admissible (KinematicState) and reports them; `report.max_depth` is the depth found at the
  /// current positions, which the impulses of the step before should have kept near zero.
  virtual ContactReport constrain(const SurfaceCells& /*surface*/, KinematicState& /*state*/) {
    return {};
  }
  /// Saves or loads what one evaluation leaves for the next (a checkpoint); nothing by default.
  virtual void archive(StateArchive& /*a*/) {}
};

/// A law enforced exactly by impulses (ExactPlane, ExactSurfaceContact): it adds no force of the
/// current configuration, and lists in touched() the pairs its last constrain() gave impulses.
class KinematicContactLaw : public ContactLaw {
 public:
  bool kinematic() const final { return true; }
  ContactReport add_forces(const SurfaceCells& /*surface*/, const PairState& /*state*/,
                           std::span<Point> /*force*/, std::span<Point> /*velocity_force*/) final {
    touched_.clear();
    return {};
  }
  std::span<const int> touched() const final { return touched_; }
  void archive(StateArchive& a) override;

 protected:
  /// Throws InputError naming `what` unless the state has a position and a node per (cell,
  /// vertex) pair of the mesh.
  static void check_state(const PolygonMesh& mesh, const KinematicState& state,
                          const std::string& what) {
    if (state.position.size() != static_cast<std::size_t>(mesh.offsets().back()) ||
        state.node.size() != state.position.size())
      throw InputError(what + ": expected a position and a node per (cell, vertex) pair, " +
                       std::to_string(mesh.offsets().back()) + "; found " +
                       std::to_string(state.position.size()) + " and " +
                       std::to_string(state.node.size()));
  }

  std::vector<int> touched_;
};

}  // namespace vorodg
