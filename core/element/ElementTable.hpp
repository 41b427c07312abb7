#pragma once
// The element table: the one thing CG and DG both consume. Per cell: quadrature points and
// weights on the fan from the centroid, and the values and gradients of the cell's nodal shape
// functions there (gradients divergence-corrected if asked, report Eqs. 15-16). The shape
// functions are those of the element family: RK (the report's) or generalized barycentric
// coordinates (Wachspress, mean value).
#include <Eigen/Core>
#include <memory>
#include <span>
#include <vector>

#include "core/element/ElementFamily.hpp"
#include "core/element/RkShapeFunctions.hpp"
#include "core/element/WeightFunctions.hpp"
#include "core/mesh/PolygonMesh.hpp"

namespace vorodg {

/// The words of the one-line refusal of a non-convex cell by the Wachspress element, which a
/// report can look for to tell a refusal from a breakdown.
inline constexpr const char* kNotConvexCell = "is not strictly convex at its vertex";

struct ElementOptions {
  ElementFamily family = ElementFamily::rk;  // the shape functions (rk: the weights below)
  /// vem: the stabilization's scale tau, times trace(K_consistency) / (2n) (VirtualElement.hpp)
  double vem_stabilization = 1.0;
  int rule_points = 3;  // per fan triangle: 1, 3 or 6 (vem: one point per cell, see there)
  bool divergence_correction = true;  // enforce the discrete divergence identity (Eq. 16)
  WeightFunctionOptions weights;
  /// Cells congruent with an earlier one (CongruentCells: the same neighbourhood up to a
  /// translation) take its values instead of computing their own; false: every cell computed.
  bool reuse_congruent = true;
  int threads = 1;  // setup threads; results do not depend on it
  /// Keep psi at the quadrature points (what body forces and lumped masses read); false keeps
  /// only the gradients, for runs that need no more (a static solve without body force: 8 bytes
  /// per node and point less, about a third of the table).
  bool shape_values = true;
  bool operator==(const ElementOptions&) const = default;
};

/// Quadrature point of a cell: fan triangle and barycentric coordinates (centroid, v_k, v_k+1).
struct FanPoint {
  int fan = 0;
  Eigen::Vector3d bary;
};

class ElementTable {
 public:
  /// Builds weight functions, quadrature and shape functions for every cell. Throws InputError
  /// naming the cell if one is not star-shaped with respect to its centroid, NumericalError if
  /// a moment matrix is singular at a quadrature point.
  ElementTable(const PolygonMesh& mesh, const ElementOptions& options);

  const PolygonMesh& mesh() const { return mesh_; }
  /// The cell's centroid: the apex of its quadrature fan.
  const Point& centroid(int c) const { return centroids_[c]; }
  const ElementOptions& options() const { return options_; }
  /// The RK weight functions (not between release_weights() and restore_weights(); none for
  /// the other families).
  const WeightFunctions& weights() const;
  /// Sub-triangles per fan-triangle edge of the weight functions' lattice, 2^refinement, which
  /// the error quadrature uses for every family so that errors compare across families.
  int lattice_size() const { return 1 << options_.weights.refinement; }

  int num_points(int c) const { return point_offsets_[c + 1] - point_offsets_[c]; }
  int num_nodes(int c) const { return mesh_.cell_size(c); }
  const Point& point(int c, int q) const { return points_[point_offsets_[c] + q]; }
  double weight(int c, int q) const { return weights_q_[point_offsets_[c] + q]; }
  /// The weights of all of cell c's quadrature points.
  std::span<const double> weights(int c) const {
    return {weights_q_.data() + point_offsets_[c], std::size_t(num_points(c))};
  }
  const FanPoint& fan_point(int c, int q) const { return fan_points_[point_offsets_[c] + q]; }
  /// Whether psi is kept at the quadrature points (ElementOptions::shape_values).
  bool has_shape_values() const { return options_.shape_values; }
  /// psi_k and grad psi_k of the cell's vertex k at quadrature point q (psi only if kept).
  double shape(int c, int q, int k) const {
    return shape_[value_offsets_[c] + q * num_nodes(c) + k];
  }
  const Eigen::Vector2d& grad(int c, int q, int k) const {
    return grad_[value_offsets_[c] + q * num_nodes(c) + k];
  }

  /// The cell whose shape functions c shares (CongruentCells; c itself when it shares none), and
  /// how many cells share them.
  int representative(int c) const { return representative_.empty() ? c : representative_[c]; }
  int class_size(int c) const { return class_size_.empty() ? 1 : class_size_[representative(c)]; }
  /// Classes of congruent cells (the number of cells without reuse).
  int num_classes() const { return classes_; }

  /// Largest |sum_q w_q dpsi_k/dx_i - (boundary integral)| over the cell's nodes and directions
  /// before any correction: the discrete divergence defect (Eq. 16), absolute.
  double divergence_defect(int c) const { return defect_[c]; }
  /// Smallest reciprocal condition estimate of the RK moment matrix over the cell's points (1
  /// for the families without one).
  double min_moment_rcond(int c) const { return rcond_[c]; }
  /// Smallest value of the cell's RK vertex weight functions over its quadrature points (> 0;
  /// 1 for the families without them).
  double min_weight(int c) const { return min_weight_[c]; }
  /// Below this reciprocal condition estimate a moment matrix counts as singular.
  static constexpr double kMinMomentRcond = 1e-14;

  /// Shape functions (uncorrected gradients) at any point of the cell given as fan triangle and
  /// barycentric coordinates. On the cell's edges (barycentric centroid coordinate 0) the values
  /// are the exact edge limit, linear between the edge's two vertices.
  void evaluate(int c, const FanPoint& at, double* psi, Eigen::Vector2d* grad) const;
  /// The same at several points of cell c (point after point: psi and grad have at.size() x
  /// cell_size entries). The cell's setup is shared, and each run of points on one fan
  /// triangle evaluates its weight functions in one pass: list a fan's points together.
  void evaluate_points(int c, std::span<const FanPoint> at, double* psi,
                       Eigen::Vector2d* grad) const;
  Point position(int c, const FanPoint& at) const;

  /// Frees the values, gradients and weights stored at the quadrature points (and the points),
  /// about 3.6 KB per hexagon, once the cell matrices and cell mean operators are built: a CG
  /// solve then factors without them (at 1e6 cells, 3.7 GB). Afterwards only evaluate(),
  /// position() and the per-cell data are available.
  void release_point_values();
  /// Frees the weight functions' nodal values too (about 0.9 KB per hexagon at the default
  /// setting, 0.9 GB at 1e6 cells) while a factorization needs the memory. evaluate(),
  /// position() and weights() need them back: restore_weights() computes them again, the same
  /// to the bit.
  void release_weights();
  void restore_weights();
  /// Bytes the weight functions hold (0 when released or for the families without them).
  std::size_t weights_bytes() const { return weights_ ? weights_->bytes() : 0; }
  /// Whether restore_weights() has anything to compute (RK weights released).
  bool weights_released() const { return !weights_ && options_.family == ElementFamily::rk; }

 private:
  void build_cell(int c);
  /// Cell c's values from its representative r's (points from c's own geometry).
  void copy_cell(int c, int r);
  void build_virtual_element_cell(int c, std::span<const Eigen::Vector2d> nodes);
  /// Eq. 16's gap for each node of cell c, recorded, and closed if the correction is on.
  void close_divergence_gap(int c, std::span<const Eigen::Vector2d> nodes);
  /// Quadrature points of an n-gon: the fan rule's per fan triangle, or one (vem).
  int points_per_cell(int n, int per_fan) const;
  RkCellFrame cell_frame(int c) const;
  /// Where cell c's psi values go, from the cell's value `offset` on: the table, or scratch
  /// space of this thread when they are not kept.
  double* shape_out(int c, std::size_t offset);
  /// psi_k and grad psi_k of the family at points strictly inside cell c, all on fan triangle
  /// `fan` (barycentric `bary`, positions `x`; point after point in psi and grad); the smallest
  /// RK moment-matrix reciprocal condition estimate over them (0 for a non-finite value), or 1.
  double fan_shape_functions(int c, std::span<const Eigen::Vector2d> nodes,
                             std::span<const Eigen::Vector3d> node_basis, int fan,
                             std::span<const Eigen::Vector3d> bary, const Point* x, double* psi,
                             Eigen::Vector2d* grad, double* min_weight) const;

  const PolygonMesh& mesh_;
  ElementOptions options_;
  std::unique_ptr<WeightFunctions> weights_;
  std::vector<Point> centroids_;
  std::vector<double> scales_;  // sqrt(area): the RK frame's length, once per cell
  std::vector<int> point_offsets_;
  std::vector<std::size_t> value_offsets_;
  std::vector<Point> points_;
  std::vector<double> weights_q_;
  std::vector<FanPoint> fan_points_;
  std::vector<double> shape_;
  std::vector<Eigen::Vector2d> grad_;
  std::vector<double> defect_, rcond_, min_weight_;
  std::vector<int> representative_, class_size_;  // empty: no reuse
  int classes_ = 0;
};

}  // namespace vorodg
