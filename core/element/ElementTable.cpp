#include "core/element/ElementTable.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "core/element/BarycentricCoordinates.hpp"
#include "core/element/CongruentCells.hpp"
#include "core/element/RkShapeFunctions.hpp"
#include "core/element/VirtualElement.hpp"
#include "core/geometry/Polygon.hpp"
#include "core/quadrature/TriangleRule.hpp"
#include "core/util/Errors.hpp"
#include "core/util/Format.hpp"

namespace vorodg {
namespace {

constexpr int kMaxNodes = 64;  // cells with more vertices are rejected

void check_element_options(const ElementOptions& o) {
  if (std::find(kFanRulePoints.begin(), kFanRulePoints.end(), o.rule_points) ==
      kFanRulePoints.end())
    throw InputError("quadrature rule with " + std::to_string(o.rule_points) +
                     " points per fan triangle: expected 1, 3 or 6");
  check_weight_options(o.weights);
}

/// Fan quadrature needs every triangle (centroid, v_k, v_k+1) to be positive.
void check_star_shaped(const PolygonMesh& mesh) {
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto pts = mesh.cell_points(c);
    if (static_cast<int>(pts.size()) > kMaxNodes)
      throw InputError("cell " + std::to_string(c) + " has " + std::to_string(pts.size()) +
                       " vertices, expected at most " + std::to_string(kMaxNodes));
    const double area = polygon::signed_area(pts);
    if (!(area > 0.0) || !polygon::star_shaped_about(pts, polygon::centroid(pts, area), 0.0))
      throw InputError(
          "cell " + std::to_string(c) +
          " is not star-shaped with respect to its centroid (fan quadrature needs it)");
  }
}

/// Wachspress coordinates need every corner to turn counter-clockwise.
void check_convex(const PolygonMesh& mesh) {
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto pts = mesh.cell_points(c);
    const int k = first_non_convex_corner(pts);
    if (k >= 0)
      throw InputError("cell " + std::to_string(c) + " " + kNotConvexCell + " " +
                       std::to_string(mesh.cell_vertices(c)[k]) +
                       " (element wachspress needs convex cells; mean-value takes any "
                       "star-shaped cell)");
  }
}

BarycentricKind barycentric_kind(ElementFamily family) {
  return family == ElementFamily::wachspress ? BarycentricKind::wachspress
                                             : BarycentricKind::mean_value;
}

/// The cell's vertices, in loop order, into `nodes` (kMaxNodes long).
std::span<const Eigen::Vector2d> cell_nodes(const PolygonMesh& mesh, int c,
                                            Eigen::Vector2d* nodes) {
  const auto loop = mesh.cell_vertices(c);
  for (std::size_t k = 0; k < loop.size(); ++k) nodes[k] = mesh.vertex(loop[k]);
  return {nodes, loop.size()};
}

}  // namespace

ElementTable::ElementTable(const PolygonMesh& mesh, const ElementOptions& options)
    : mesh_(mesh), options_(options) {
  check_element_options(options);
  check_star_shaped(mesh);
  if (options.family == ElementFamily::wachspress) check_convex(mesh);
  const int nc = mesh.num_cells();
  classes_ = nc;
  if (options.reuse_congruent) {
    const CongruentCells congruent(mesh);
    classes_ = congruent.num_classes();
    if (classes_ < nc) {
      representative_.resize(nc), class_size_.resize(nc);
      for (int c = 0; c < nc; ++c)
        representative_[c] = congruent.representative(c), class_size_[c] = congruent.class_size(c);
    }
  }
  if (options.family == ElementFamily::rk)
    weights_ =
        std::make_unique<WeightFunctions>(mesh, options.weights, options.threads, representative_);
  const int q_per_fan = triangle_rule(options.rule_points).size();
  centroids_.resize(nc);
  scales_.resize(nc);
  for (int c = 0; c < nc; ++c) {
    centroids_[c] = mesh.cell_centroid(c);
    scales_[c] = std::sqrt(mesh.cell_area(c));
  }
  point_offsets_.assign(nc + 1, 0);
  value_offsets_.assign(nc + 1, 0);
  for (int c = 0; c < nc; ++c) {
    const int n = mesh.cell_size(c);
    const int points = points_per_cell(n, q_per_fan);
    point_offsets_[c + 1] = point_offsets_[c] + points;
    value_offsets_[c + 1] = value_offsets_[c] + static_cast<std::size_t>(n) * points;
  }
  points_.resize(point_offsets_.back());
  weights_q_.resize(point_offsets_.back());
  fan_points_.resize(point_offsets_.back());
  if (options.shape_values) shape_.resize(value_offsets_.back());
  grad_.resize(value_offsets_.back());
  defect_.assign(nc, 0.0);
  rcond_.assign(nc, 0.0);
  min_weight_.assign(nc, 0.0);

  // Exceptions must not leave a parallel region: remember the first failing cell instead.
  std::atomic<int> failed{nc};
  const int threads = std::max(options.threads, 1);
#pragma omp parallel for schedule(dynamic, 256) num_threads(threads)
  for (int c = 0; c < nc; ++c) {
    if (representative(c) != c) continue;
    build_cell(c);
    if (!(rcond_[c] > kMinMomentRcond) || !(min_weight_[c] > 0.0)) {
      int expected = failed.load();
      while (c < expected && !failed.compare_exchange_weak(expected, c)) {
      }
    }
  }
  if (!representative_.empty()) {
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int c = 0; c < nc; ++c)
      if (representative_[c] != c) copy_cell(c, representative_[c]);
  }
  if (failed < nc) {
    const int c = failed.load();
    // A weight function must be positive wherever the cell's shape functions are evaluated:
    // every vertex's patch contains the cell. A zero or negative one makes the moment matrix
    // indefinite or leaves a node without influence.
    if (options.family != ElementFamily::rk)
      throw NumericalError("cell " + std::to_string(c) +
                           ": its barycentric coordinates are not finite at a quadrature point "
                           "(a degenerate cell)");
    if (!(min_weight_[c] > 0.0))
      throw NumericalError("cell " + std::to_string(c) + ": a vertex weight function is " +
                           fmt(min_weight_[c]) +
                           " <= 0 at a quadrature point (expected > 0 inside "
                           "the cell; a degenerate cell or weight sub-triangle)");
    throw NumericalError("cell " + std::to_string(c) +
                         ": the RK moment matrix is singular at a quadrature point (reciprocal "
                         "condition " +
                         fmt(rcond_[c]) + ", expected > " + fmt(kMinMomentRcond) + ")");
  }
}

void ElementTable::build_cell(int c) {
  const int n = mesh_.cell_size(c);
  const Point& C = centroids_[c];
  Eigen::Vector2d node_storage[kMaxNodes];
  const auto nodes = cell_nodes(mesh_, c, node_storage);
  Eigen::Vector3d node_basis[kMaxNodes];
  if (options_.family == ElementFamily::rk) rk_node_basis(cell_frame(c), nodes, node_basis);
  if (options_.family == ElementFamily::vem) {
    build_virtual_element_cell(c, nodes);
    return;
  }
  const TriangleRule& rule = triangle_rule(options_.rule_points);
  const int per_fan = rule.size();
  double min_rcond = std::numeric_limits<double>::infinity();
  double min_weight = std::numeric_limits<double>::infinity();
  for (int k = 0; k < n; ++k) {
    const Point& A = nodes[k];
    const Point& B = nodes[(k + 1) % n];
    const double fan_area = 0.5 * polygon::orient2(C, A, B);
    const std::size_t first = point_offsets_[c] + static_cast<std::size_t>(k) * per_fan;
    for (int r = 0; r < per_fan; ++r) {
      fan_points_[first + r] = {k, rule.bary[r]};
      points_[first + r] = rule.bary[r][0] * C + rule.bary[r][1] * A + rule.bary[r][2] * B;
      weights_q_[first + r] = rule.weights[r] * fan_area;
    }
    const std::size_t v = value_offsets_[c] + static_cast<std::size_t>(k) * per_fan * n;
    min_rcond = std::min(
        min_rcond,
        fan_shape_functions(c, nodes, {node_basis, static_cast<std::size_t>(n)}, k,
                            {rule.bary.data(), static_cast<std::size_t>(per_fan)}, &points_[first],
                            shape_out(c, v - value_offsets_[c]), &grad_[v], &min_weight));
  }
  rcond_[c] = std::min(min_rcond, 1.0);  // 1 for the families without a moment matrix
  min_weight_[c] = options_.family == ElementFamily::rk ? min_weight : 1.0;
  close_divergence_gap(c, nodes);
}

void ElementTable::copy_cell(int c, int r) {
  const int points = num_points(c);
  for (int q = 0; q < points; ++q) {
    const std::size_t to = point_offsets_[c] + q, from = point_offsets_[r] + q;
    fan_points_[to] = fan_points_[from];
    weights_q_[to] = weights_q_[from];
    points_[to] = position(c, fan_points_[to]);
  }
  if (options_.shape_values)
    std::copy_n(shape_.begin() + value_offsets_[r], value_offsets_[r + 1] - value_offsets_[r],
                shape_.begin() + value_offsets_[c]);
  std::copy_n(grad_.begin() + value_offsets_[r], value_offsets_[r + 1] - value_offsets_[r],
              grad_.begin() + value_offsets_[c]);
  defect_[c] = defect_[r], rcond_[c] = rcond_[r], min_weight_[c] = min_weight_[r];
}

/// The virtual element's one point, the centroid with the cell's area: its projected strain is
/// constant, so one point integrates the consistency stiffness exactly, and its load is the
/// usual first-order one (the projected basis times the load at the centroid).
void ElementTable::build_virtual_element_cell(int c, std::span<const Eigen::Vector2d> nodes) {
  const std::size_t at = point_offsets_[c];
  fan_points_[at] = {0, Eigen::Vector3d(1.0, 0.0, 0.0)};
  points_[at] = centroids_[c];
  const double area = mesh_.cell_area(c);
  weights_q_[at] = area;
  VemProjection(nodes, area).basis(points_[at], shape_out(c, 0), &grad_[value_offsets_[c]]);
  rcond_[c] = 1.0;
  min_weight_[c] = 1.0;
  close_divergence_gap(c, nodes);
}

void ElementTable::close_divergence_gap(int c, std::span<const Eigen::Vector2d> nodes) {
  const int n = static_cast<int>(nodes.size());
  // Discrete divergence identity (Eq. 16): sum_q w_q dpsi_k/dx_i must equal the boundary
  // integral of psi_k n_i, which for edge-linear psi_k is half the sum of (length x normal) of
  // the two cell edges at vertex k: 0.5 (y_k+1 - y_k-1, x_k-1 - x_k+1).
  const int nq = num_points(c);
  double sum_w2 = 0.0;
  for (int j = 0; j < nq; ++j) sum_w2 += weight(c, j) * weight(c, j);
  double defect = 0.0;
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d boundary =
        polygon::vertex_hat_flux(nodes[(k + n - 1) % n], nodes[(k + 1) % n]);
    Eigen::Vector2d volume = Eigen::Vector2d::Zero();
    for (int j = 0; j < nq; ++j) volume += weight(c, j) * grad(c, j, k);
    const Eigen::Vector2d gap = boundary - volume;
    defect = std::max(defect, gap.cwiseAbs().maxCoeff());
    if (!options_.divergence_correction) continue;
    // Least change of the gradients (in the sum of squares) that closes the gap.
    for (int j = 0; j < nq; ++j)
      grad_[value_offsets_[c] + static_cast<std::size_t>(j) * n + k] += weight(c, j) * gap / sum_w2;
  }
  defect_[c] = defect;
}

int ElementTable::points_per_cell(int n, int per_fan) const {
  return options_.family == ElementFamily::vem ? 1 : n * per_fan;
}

double* ElementTable::shape_out(int c, std::size_t offset) {
  if (options_.shape_values) return &shape_[value_offsets_[c] + offset];
  thread_local std::vector<double> scratch;
  scratch.resize(std::max(scratch.size(), value_offsets_[c + 1] - value_offsets_[c]));
  return scratch.data() + offset;
}

RkCellFrame ElementTable::cell_frame(int c) const {
  return {centroids_[c], scales_[c]};
}

double ElementTable::fan_shape_functions(int c, std::span<const Eigen::Vector2d> nodes,
                                         std::span<const Eigen::Vector3d> node_basis, int fan,
                                         std::span<const Eigen::Vector3d> bary, const Point* x,
                                         double* psi, Eigen::Vector2d* grad,
                                         double* min_weight) const {
  const int n = static_cast<int>(nodes.size());
  const std::size_t points = bary.size();
  double min_rcond = std::numeric_limits<double>::infinity();
  auto keep = [&](double rc) { min_rcond = std::min(min_rcond, std::isfinite(rc) ? rc : 0.0); };
  if (options_.family == ElementFamily::vem) {  // the projection: what a virtual element knows
    const VemProjection projection(nodes, mesh_.cell_area(c));
    for (std::size_t p = 0; p < points; ++p) projection.basis(x[p], psi + p * n, grad + p * n);
    return 1.0;
  }
  if (options_.family != ElementFamily::rk) {
    for (std::size_t p = 0; p < points; ++p) {
      double* ps = psi + p * n;
      Eigen::Vector2d* gr = grad + p * n;
      barycentric_coordinates(barycentric_kind(options_.family), nodes, x[p], ps, gr);
      bool finite = true;
      for (int k = 0; k < n; ++k) finite = finite && std::isfinite(ps[k]) && gr[k].allFinite();
      keep(finite ? 1.0 : 0.0);
    }
    return min_rcond;
  }
  // The weight functions of the fan's points in one pass (the fan's geometry set up once).
  thread_local std::vector<double> w;
  thread_local std::vector<Eigen::Vector2d> grad_w;
  w.resize(points * n);
  grad_w.resize(points * n);
  weights().evaluate_fan(c, fan, bary, w.data(), grad_w.data());
  for (double wj : w) *min_weight = std::min(*min_weight, std::isnan(wj) ? -1.0 : wj);
  const RkCellFrame frame = cell_frame(c);
  for (std::size_t p = 0; p < points; ++p)
    keep(rk_shape_functions(frame, node_basis, x[p], &w[p * n], &grad_w[p * n], psi + p * n,
                            grad + p * n));
  return min_rcond;
}

Point ElementTable::position(int c, const FanPoint& at) const {
  const auto loop = mesh_.cell_vertices(c);
  const int n = static_cast<int>(loop.size());
  return at.bary[0] * centroids_[c] + at.bary[1] * mesh_.vertex(loop[at.fan]) +
         at.bary[2] * mesh_.vertex(loop[(at.fan + 1) % n]);
}

void ElementTable::evaluate(int c, const FanPoint& at, double* psi, Eigen::Vector2d* grad) const {
  evaluate_points(c, {&at, 1}, psi, grad);
}

void ElementTable::evaluate_points(int c, std::span<const FanPoint> at, double* psi,
                                   Eigen::Vector2d* grad) const {
  const int n = mesh_.cell_size(c);
  Eigen::Vector2d node_storage[kMaxNodes];
  const auto nodes = cell_nodes(mesh_, c, node_storage);
  Eigen::Vector3d node_basis[kMaxNodes];
  if (options_.family == ElementFamily::rk) rk_node_basis(cell_frame(c), nodes, node_basis);
  // On the cell's edge the RK moment matrix is singular and Wachspress's weights vanish; the
  // gradient is the one-sided limit from just inside.
  constexpr double kInside = 1e-9;
  thread_local std::vector<Eigen::Vector3d> bary;
  thread_local std::vector<Point> x;
  double min_weight = 1.0;
  for (std::size_t first = 0; first < at.size();) {  // one run of points of one fan at a time
    const int fan = at[first].fan;
    std::size_t last = first;
    bary.clear(), x.clear();
    for (; last < at.size() && at[last].fan == fan; ++last) {
      Eigen::Vector3d b = at[last].bary;
      if (b[0] < kInside) b = Eigen::Vector3d(kInside, b[1] * (1 - kInside), b[2] * (1 - kInside));
      bary.push_back(b);
      x.push_back(position(c, FanPoint{fan, b}));
    }
    fan_shape_functions(c, nodes, {node_basis, static_cast<std::size_t>(n)}, fan, bary, x.data(),
                        psi + first * n, grad + first * n, &min_weight);
    for (std::size_t p = first; p < last; ++p) {
      if (at[p].bary[0] >= kInside) continue;
      // Exact edge limit: linear between the edge's end points.
      const double s = at[p].bary[1] + at[p].bary[2];
      double* ps = psi + p * n;
      for (int k = 0; k < n; ++k) ps[k] = 0.0;
      ps[fan] = at[p].bary[1] / s;
      ps[(fan + 1) % n] = at[p].bary[2] / s;
    }
    first = last;
  }
}

const WeightFunctions& ElementTable::weights() const {
  if (!weights_) throw NumericalError("internal: the weight functions were released");
  return *weights_;
}

void ElementTable::release_weights() {
  weights_.reset();
}

void ElementTable::restore_weights() {
  if (!weights_ && options_.family == ElementFamily::rk)
    weights_ = std::make_unique<WeightFunctions>(mesh_, options_.weights, options_.threads,
                                                 representative_);
}

void ElementTable::release_point_values() {
  std::vector<Point>().swap(points_);
  std::vector<double>().swap(weights_q_);
  std::vector<FanPoint>().swap(fan_points_);
  std::vector<double>().swap(shape_);
  std::vector<Eigen::Vector2d>().swap(grad_);
}

}  // namespace vorodg
