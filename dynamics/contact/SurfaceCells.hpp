#pragma once
// The cells that take part in contact, and which of their edges are free surface. The set starts
// as the cells with a boundary edge and only grows: a crack exposes new surface, and nothing
// ever heals in a fracture run, so a cell never leaves. Growth is the only change, which keeps
// the bookkeeping O(1) per call and the order of the cells (the order they entered) stable.
//
// Cells that share a mesh vertex are never tested against each other (`neighbours`). Adjacent
// cells touch along their common edge or vertex by construction, so every step would find them
// "in contact" at zero depth, and round-off would turn that into spurious forces. Across a crack
// between two such cells, overclosure is the cohesive law's business (its contact penalty in
// the fracture code), not this module's, until the crack's faces have come apart and the law
// releases them (`release`): from then on the two cells across that edge are tested like any
// others. The price: two cells that share only a vertex, and fragments that fold back onto a
// cell they once touched at a vertex alone, do not see each other.
#include <span>
#include <vector>

#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

class StateArchive;

class SurfaceCells {
 public:
  /// The cells with a boundary edge, in increasing index; their boundary edges are exposed.
  /// The mesh is the reference mesh and must outlive this object.
  explicit SurfaceCells(const PolygonMesh& mesh);

  /// Adds a cell (a crack reached it). Idempotent: returns false if it was already in.
  /// Throws InputError for an index out of range.
  bool add(int cell);
  /// Marks mesh edge e as free surface (a crack opened along it) and adds its one or two
  /// cells. Idempotent. A penetrating vertex is pushed out through the nearest exposed edge of
  /// the cell it is in, so exposing the crack faces lets fragments push each other out through
  /// them rather than through an edge still bonded to the rest of the body.
  void expose(int edge);

  int size() const { return static_cast<int>(cells_.size()); }
  /// The cells, in the order they entered.
  std::span<const int> cells() const { return cells_; }
  bool contains(int cell) const { return member_[cell] != 0; }
  /// Whether local edge k of cell c is exposed.
  bool exposed(int cell, int k) const { return exposed_[mesh_->offsets()[cell] + k] != 0; }
  /// One flag per local edge of the cell (the mesh's CSR layout).
  std::span<const char> exposed_edges(int cell) const {
    const auto& o = mesh_->offsets();
    return {exposed_.data() + o[cell], exposed_.data() + o[cell + 1]};
  }
  bool has_exposed_edge(int cell) const;
  /// Mesh edge e, already exposed, has let go: the faces of its crack are apart, and its two
  /// cells are no longer neighbours across it. Idempotent. Throws InputError for an edge that
  /// is not an exposed interior edge.
  void release(int edge);
  /// True if a and b share a vertex of the reference mesh (a cell is its own neighbour) and no
  /// released edge lies between them: such cells are never tested against each other.
  bool neighbours(int a, int b) const;

  const PolygonMesh& mesh() const { return *mesh_; }
  /// Changes whenever the set of cells or of released edges does (both only grow): what a
  /// cached candidate list depends on.
  long revision() const { return static_cast<long>(cells_.size()) + num_released_; }

  /// Saves or loads which cells and edges are surface and which faces were released.
  void archive(StateArchive& a);

 private:
  void check_cell(int cell) const;
  void check_edge(int edge) const;
  /// The position of `edge` in the loop of `cell`, which must have it.
  int local_index(int cell, int edge) const;
  /// Whether a and b, two cells, meet across a released edge.
  bool released_between(int a, int b) const;

  const PolygonMesh* mesh_;
  std::vector<char> member_;    // per cell
  std::vector<int> cells_;      // members, in order of entry
  std::vector<char> exposed_;   // per (cell, local edge), CSR like the cells' loops
  std::vector<char> released_;  // per mesh edge
  int num_released_ = 0;
};

}  // namespace vorodg
