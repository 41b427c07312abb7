#pragma once
// Extrinsic crack insertion for explicit dynamics (report sections 4 and 6): after a step, every
// intact interior edge that may crack is checked against the Mohr-Coulomb criterion with tensile
// cutoff (the same MohrCoulomb as quasi-static fracture), on the traction of the mean of its two
// cells' stresses, sigma = (sigma_0 + sigma_1) / 2:
//     normal = n . sigma n  (tension positive),   shear = t . sigma n.
// Each cell's stress is its mean stress D B_c u_c (B_c the cell mean of the strain operator),
// which is what the element integrates exactly; a stress at the edge itself would need the shape
// functions' gradients there, which are one-sided and noisier on small RK cells.
//
// Which edges may crack is the scene's business (every interior edge, or a subset): the object
// takes the mask. Cell stresses are computed in parallel into their own slots and edges are
// checked in order, so the list of failing edges does not depend on the thread count.
#include <Eigen/Core>
#include <span>
#include <vector>

#include "core/dofs/SplitDofMap.hpp"
#include "core/element/ElasticityIntegrator.hpp"
#include "core/mesh/PolygonMesh.hpp"
#include "core/random/MaterialVariation.hpp"
#include "dynamics/CorotationalFrames.hpp"
#include "fracture/MohrCoulomb.hpp"

namespace vorodg {

class CrackInsertion {
 public:
  /// `eligible[e]` per mesh edge (boundary entries ignored). `mesh` must outlive this object.
  /// Throws InputError if the mask's size is not the mesh's number of edges.
  CrackInsertion(const PolygonMesh& mesh, const ElasticityIntegrator& integrator,
                 const MohrCoulomb& criterion, std::vector<char> eligible, int threads = 1);

  /// A material varying from cell to cell: each cell's stresses scale with its stiffness factor,
  /// and each edge's criterion with its strength factor (its cohesion and cutoff). Call before
  /// the first check.
  void vary(const MaterialVariation& variation);
  /// Corotational kinematics: each cell's stress from its displacements in its turning frame
  /// (InternalForce::frames()), in which the edges keep their reference normals. `frames` must
  /// outlive this object; nullptr for small rotations.
  void turn_with(const CorotationalFrames* frames) { frames_ = frames; }

  /// Mean stress (Voigt xx, yy, xy) of every cell at node displacements u of `dofs` (in the
  /// cell's turning frame under turn_with). Under turning frames, `local` may hold every cell's
  /// local displacements at u (InternalForce::local_displacements, 2 per pair), which are then
  /// read instead of turning each cell again; the stresses are the same to the bit.
  Eigen::Matrix3Xd cell_stresses(const SplitDofMap& dofs, const Eigen::VectorXd& u, int threads,
                                 std::span<const double> local = {}) const;
  /// The traction (normal, shear) on interior edge e from the given cell stresses, in the frame
  /// of CohesiveForces (normal out of the edge's cell0, tangent v0 -> v1).
  Eigen::Vector2d traction(const Eigen::Matrix3Xd& stresses, int e) const;
  struct Failure {
    int edge;
    Eigen::Vector2d traction;  // at the check, (normal, shear)
  };
  /// The eligible interior edges not yet `cracked` whose criterion utilization is at least 1,
  /// ascending, with their tractions.
  std::vector<Failure> failing_edges(const SplitDofMap& dofs, const Eigen::VectorXd& u,
                                     const std::vector<char>& cracked, int threads,
                                     std::span<const double> local = {}) const;

 private:
  const PolygonMesh& mesh_;
  // Per cell, D times the cell mean of the strain operator (3 x 2n, column-major, cells one after
  // another): the mean stress is this times the cell's DOFs, summed vertex by vertex without
  // gathering them (the check runs after every step, so it allocates nothing).
  std::vector<std::size_t> offset_;
  std::vector<double> stress_operator_;
  std::vector<Eigen::Vector2d> tangent_;  // per edge, v0 -> v1, unit
  MohrCoulomb criterion_;
  /// The edges the check may evaluate (eligible and interior), ascending, with their cells and
  /// strength factors (1 for a uniform material): the check's loop reads nothing else of an
  /// edge until the screen lets it through.
  struct Checked {
    int edge, cell0, cell1;
    double strength;
  };
  std::vector<Checked> checked_;
  const CorotationalFrames* frames_ = nullptr;
};

}  // namespace vorodg
