#pragma once
// Nodal weight functions of the RK polygon element (report Eq. 11, boundary conditions as
// docs/design.md reads them): for each vertex I, -lap w = 1 on its patch (the cells around I),
// w = 0 on every patch edge not incident to I, dw/dn = 0 on the domain-boundary edges incident
// to I. Solved by finite elements (P1 or P2) on each cell's fan lattice; the cell lattices of
// neighbouring cells match along shared edges, so the patch problem is conforming.
#include <Eigen/Core>
#include <array>
#include <span>
#include <vector>

#include "core/element/FanLattice.hpp"
#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

/// Default: one quadratic (P2) triangle per fan triangle. On the beam (rcp and perturbed-hex,
/// about 1e4 cells) it comes within 8-17% of the L2 error of the finest weights tried, at about
/// twice the setup cost of one linear triangle per fan (which is 44-50% off) and at the cost of
/// P1 refined once (44-65% off). See docs/element.md.
struct WeightFunctionOptions {
  int refinement = 0;  // each fan triangle cut into 4^refinement sub-triangles
  int degree = 2;      // 1 (P1) or 2 (P2) on the sub-triangles
  /// Solve small lattices (up to 64 nodes per cell, the default's 3n + 1 among them) by
  /// eliminating each cell's inner nodes once for all its vertices; false: one solve per patch
  /// (always so for larger lattices). The same weights to round-off.
  bool condense = true;
  bool operator==(const WeightFunctionOptions&) const = default;
};

/// The weight-function options a user may choose: degrees, and refinement 0..kMaxWeightRefinement.
inline constexpr std::array<int, 2> kWeightDegrees = {1, 2};
inline constexpr int kMaxWeightRefinement = 4;

/// Throws InputError unless refinement is in 0..4 and degree is 1 or 2 (P1 needs refinement
/// >= 0; note P1 with refinement 0 has no node inside a fan triangle).
void check_weight_options(const WeightFunctionOptions& options);

class WeightFunctions {
 public:
  /// Solves every vertex patch problem. `threads` > 1 runs patches in parallel; the result does
  /// not depend on the thread count. With `representative` (per cell, CongruentCells: a cell
  /// whose neighbourhood is a translate of an earlier cell's), a cell that is not its own
  /// representative takes its representative's values, and a patch of such cells only is not
  /// solved (condensed lattices only; the other path solves every patch).
  WeightFunctions(const PolygonMesh& mesh, const WeightFunctionOptions& options, int threads = 1,
                  std::span<const int> representative = {});

  const WeightFunctionOptions& options() const { return options_; }
  /// Sub-triangles per fan-triangle side.
  int lattice_size() const { return 1 << options_.refinement; }
  FanLattice lattice(int cell) const { return FanLattice(mesh_.cell_size(cell), divisions()); }
  /// Cell-local nodal values (FanLattice numbering) of the weight function of the cell's
  /// vertex k, restricted to the cell.
  std::span<const double> values(int cell, int k) const {
    const int n = lattice(cell).node_count();
    return {values_.data() + offsets_[cell] + static_cast<std::size_t>(k) * n,
            static_cast<std::size_t>(n)};
  }

  /// Values and gradients of the weight functions of all of the cell's vertices at barycentric
  /// point `bary` (centroid, v_k, v_k+1) of fan triangle k. `w` and `grad` have cell_size
  /// entries.
  void evaluate(int cell, int fan, const Eigen::Vector3d& bary, double* w,
                Eigen::Vector2d* grad) const;
  /// The same at several points of fan triangle `fan` (point after point: `w` and `grad` have
  /// points.size() x cell_size entries), the fan's geometry set up once.
  void evaluate_fan(int cell, int fan, std::span<const Eigen::Vector3d> points, double* w,
                    Eigen::Vector2d* grad) const;

  /// Bytes held: the nodal values, their offsets and the centroids.
  std::size_t bytes() const {
    return values_.size() * sizeof(double) + offsets_.size() * sizeof(std::size_t) +
           centroids_.size() * sizeof(Point);
  }

  /// Centroids of the cells (the fan centres).
  const std::vector<Point>& centroids() const { return centroids_; }

 private:
  int divisions() const { return lattice_size() * options_.degree; }
  void solve_patch(int vertex);
  void solve_by_condensation(int threads, std::span<const int> representative);
  /// Whether cell c computes its own values (it is its representative, or there are none).
  static bool computes(std::span<const int> representative, int c) {
    return representative.empty() || representative[c] == c;
  }
  /// Position of `vertex` in the cell's loop.
  int vertex_position(int cell, int vertex) const;

  const PolygonMesh& mesh_;
  WeightFunctionOptions options_;
  std::vector<Point> centroids_;
  std::vector<std::size_t> offsets_;  // per cell, into values_
  std::vector<double> values_;
};

}  // namespace vorodg
