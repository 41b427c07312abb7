#pragma once
// The binary crack state of a mesh (report section 7, crack-state abstractions): for every
// interior edge, cracked or not, optionally with the opening w_e >= 0 of each cracked edge.
// Boundary edges carry no state (they are never cracked and count in no distance).
//
// Distances between two states of the same mesh:
//   - hamming(a, b): the number of interior edges whose state differs. It is a metric on the
//     states of one mesh (symmetric, zero iff the states are equal, triangle inequality).
//   - opening_distance(a, b), our definition of the crack-opening distance d_cfod (the report's
//     Eq. 23 is not at hand, so this is a choice, not a transcription):
//         d = sum_e |w_a(e) - w_b(e)| L_e / sum_e L_e,   sums over the interior edges e,
//     L_e the edge's length. So d is the length-weighted mean opening difference over all
//     interior edges: it has the units of an opening, lies between 0 and max_e |w_a - w_b|, and
//     is zero iff the openings agree on every interior edge. Weighting by length makes a crack
//     count by its length, not by how many edges it happens to be cut into; dividing by the
//     total interior length (rather than by the cracked length of either state) keeps it a
//     metric, since the denominator is the same for every pair of states of the mesh. On finer
//     meshes of one domain the total interior length grows like 1 / h, so d of one physical
//     crack shrinks like h: compare d across meshes of the same size only.
//
// "The same mesh" means the same PolygonMesh object (the state keeps a pointer to it, so the
// mesh must outlive the state); states of different meshes are refused with an InputError.
#include <Eigen/Core>
#include <vector>

#include "core/dofs/SplitDofMap.hpp"
#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

class CrackState {
 public:
  /// `cracked[e]` per mesh edge; entries of boundary edges are ignored. Throws InputError if
  /// the size is not the mesh's number of edges.
  CrackState(const PolygonMesh& mesh, const std::vector<char>& cracked);
  /// With openings (one per mesh edge): finite, >= 0, and 0 on every uncracked or boundary
  /// edge; anything else is refused with an InputError naming the edge.
  CrackState(const PolygonMesh& mesh, const std::vector<char>& cracked,
             const Eigen::VectorXd& openings);
  /// An interior edge is cracked when `dofs` (a map of `mesh`) does not join its two cells
  /// (SplitDofMap::joins). So an edge left unconnected whose end nodes are still joined around
  /// both of its ends (an isolated edge inside the body) is not cracked: the map has no crack
  /// there, since no node splits.
  static CrackState from_dofs(const PolygonMesh& mesh, const SplitDofMap& dofs);

  const PolygonMesh& mesh() const { return *mesh_; }
  bool cracked(int e) const { return cracked_[e] != 0; }
  /// Per mesh edge, 1 for a cracked interior edge, 0 otherwise.
  const std::vector<char>& flags() const { return cracked_; }
  int num_cracked() const { return num_cracked_; }
  bool has_openings() const { return openings_.size() > 0; }
  /// Per mesh edge (empty without openings).
  const Eigen::VectorXd& openings() const { return openings_; }

  /// Number of interior edges whose state differs. Throws InputError for different meshes.
  static int hamming(const CrackState& a, const CrackState& b);
  /// The crack-opening distance d_cfod defined above. Throws InputError for different meshes
  /// or if either state has no openings.
  static double opening_distance(const CrackState& a, const CrackState& b);

 private:
  static void require_same_mesh(const CrackState& a, const CrackState& b);

  const PolygonMesh* mesh_;
  std::vector<char> cracked_;
  Eigen::VectorXd openings_;
  int num_cracked_ = 0;
};

}  // namespace vorodg
