#pragma once
// What contact reads from the integrator each step, laid out per (cell, vertex) pair in the
// mesh's CSR order: pair p = mesh.offsets()[c] + k is vertex k of cell c. Contact works on pairs,
// not nodes, because a cell's polygon is the loop of its own pairs; the node map only serves to
// count a node once when several of its pairs see the same contact. Forces come back per pair,
// and the integrator sums the pairs of each node (add_pair_forces below does it for a
// SplitDofMap).
#include <Eigen/Core>
#include <span>
#include <vector>

#include "core/dofs/SplitDofMap.hpp"
#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

struct PairState {
  /// Current position x = X + u of each pair's node. Required.
  std::span<const Point> position;
  /// Velocity of each pair's node (central differences: the half-step velocity). Needed only
  /// when the law damps (damping_ratio > 0).
  std::span<const Point> velocity;
  /// Lumped mass of each pair's node. Needed by the mass-scaled stiffness and by damping.
  std::span<const double> mass;
  /// Node of each pair. Empty: every pair is its own node (the fully discontinuous map).
  std::span<const int> node;
  /// The time step of the mass-scaled stiffness k = alpha m / dt^2.
  double dt = 0.0;
  /// Whether the positions are those of the last evaluation (an evaluation repeated after a
  /// remap): friction then sees no tangential motion, where it would otherwise take dt v.
  bool repeated = false;

  int node_of(int pair) const { return node.empty() ? pair : node[pair]; }
};

/// Throws InputError unless `position` has one entry per pair and every other non-empty field
/// too; `what` names the caller in the message.
void check_pair_state(const PolygonMesh& mesh, const PairState& state, const char* what);

/// x = X + u per pair: X is the mesh vertex, u = (u[2n], u[2n+1]) of the pair's node n.
std::vector<Point> pair_positions(const PolygonMesh& mesh, const SplitDofMap& dofs,
                                  const Eigen::VectorXd& u);
/// A nodal vector field (two entries per node, like u) read per pair: velocities.
std::vector<Point> pair_vectors(const PolygonMesh& mesh, const SplitDofMap& dofs,
                                const Eigen::VectorXd& nodal);
/// A nodal scalar (one entry per node) read per pair: lumped masses.
std::vector<double> pair_scalars(const PolygonMesh& mesh, const SplitDofMap& dofs,
                                 const Eigen::VectorXd& nodal);
/// The node of every pair.
std::vector<int> pair_nodes(const PolygonMesh& mesh, const SplitDofMap& dofs);
/// f[2n + i] += force[p](i) for every pair p of node n.
void add_pair_forces(const PolygonMesh& mesh, const SplitDofMap& dofs, std::span<const Point> force,
                     Eigen::VectorXd& f);

}  // namespace vorodg
