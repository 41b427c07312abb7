#pragma once
// The internal force of linear elasticity on a split (cell, vertex) DOF map: f = K u assembled
// from the precomputed cell matrices, f_c = K_c u_c, without ever forming K.
//
// Determinism: every cell writes its force into its own (cell, vertex) pair slots and its
// energy into its own cell slot (parallel over cells); each node then adds its pairs' slots in
// increasing pair order (parallel over nodes). No sum depends on the thread count, so the force
// is bit-for-bit the same for any number of threads.
//
// Momentum: round-off must not create any. Each cell's displacements are taken relative to its
// first vertex (K_c annihilates translations), so a translating cell feels exactly zero force,
// and each cell's force is made self-equilibrated (the last vertex takes minus the sum of the
// others). A free body's momentum then stays constant to 1e-15 over 1e4 steps.
//
// Corotational (optional): the same with each cell's displacements taken in its own turning
// frame; the force is then the exact gradient of the cell energies, no longer linear in u.
//
// Speed: the matrices of all cells lie in one contiguous array (ElasticityIntegrator's
// CellMatrices); cells of 3 to 10 vertices use fixed-size Eigen mat-vecs; the loop allocates
// nothing. See docs/dynamics.md for the measured throughput.
#include <Eigen/Core>
#include <optional>
#include <span>
#include <vector>

#include "core/dofs/SplitDofMap.hpp"
#include "core/element/ElasticityIntegrator.hpp"
#include "core/mesh/PolygonMesh.hpp"
#include "dynamics/CorotationalFrames.hpp"
#include "dynamics/OrderedSum.hpp"

namespace vorodg {

class StateArchive;

class InternalForce {
 public:
  using CellMatrices = ElasticityIntegrator::CellMatrices;

  /// `matrices` must hold every cell of `mesh` (ElasticityIntegrator::all_cell_matrices).
  /// Throws InputError if it does not. `corotational`: each cell's small strain is taken in a
  /// frame that turns with it (CorotationalFrames), so cells may rotate through any angle.
  InternalForce(const PolygonMesh& mesh, CellMatrices matrices, bool corotational = false);

  /// f = K u over the node DOFs of `dofs`, a DOF map of the same mesh (u_x, u_y per node; f is
  /// resized), and returns the elastic energy 1/2 u.K u, the sum of the cell energies in cell
  /// order. Throws InputError if u does not have two entries per node.
  double compute(const SplitDofMap& dofs, const Eigen::VectorXd& u, Eigen::VectorXd& f,
                 int threads);
  /// The same f and energy from the last compute's cell forces, on `dofs` (which may have
  /// changed since): valid when every cell's displacements are what they were then, as after a
  /// split (which copies them), and then bit-for-bit what compute would give, for a gather's
  /// cost.
  double reassemble(const SplitDofMap& dofs, Eigen::VectorXd& f, int threads);
  /// The same as reassemble for the listed nodes alone (f must already have room for them):
  /// after a split, the nodes whose pairs changed.
  void reassemble_nodes(const SplitDofMap& dofs, std::span<const int> nodes,
                        Eigen::VectorXd& f) const;

  int num_cells() const { return static_cast<int>(offsets_.size()) - 1; }
  int cell_size(int c) const { return offsets_[c + 1] - offsets_[c]; }
  const CellMatrices& matrices() const { return K_; }
  Eigen::Map<const Eigen::MatrixXd> cell_matrix(int c) const {
    return K_.block(c, 2 * cell_size(c));
  }
  /// The cells' turning frames (nullptr for small rotations).
  const CorotationalFrames* frames() const { return frames_ ? &*frames_ : nullptr; }
  /// From the last compute: 1/2 u_c.K_c u_c per cell, and cell c's force on its vertex k
  /// (x, y) at pair_forces()[2 (offset_c + k) + d].
  std::span<const double> cell_energies() const { return cell_energy_; }
  std::span<const double> pair_forces() const { return pair_force_; }
  /// Under turning frames, every cell's local displacements u^ at the last compute (2 per
  /// pair, the pair layout); empty for small rotations. The insertion check's cell stresses read
  /// them instead of turning every cell again (CrackInsertion::cell_stresses).
  std::span<const double> local_displacements() const { return local_; }

  /// Saves or loads the last compute's cell forces and energies (a checkpoint).
  void archive(StateArchive& a);

 private:
  void cell_forces(const int* pair_node, const double* u, int threads);
  /// f at node i: its pairs' forces added in increasing pair order.
  void gather_node(const SplitDofMap& dofs, int i, double* f) const;

  std::vector<int> offsets_;  // the mesh's cell offsets: pair index = offsets_[c] + k
  CellMatrices K_;
  std::vector<double> pair_force_, cell_energy_;
  std::vector<double> local_;  // per pair, under turning frames
  OrderedSum energy_sum_;
  std::optional<CorotationalFrames> frames_;
};

}  // namespace vorodg
