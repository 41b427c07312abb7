#include "core/problem/ErrorNorms.hpp"

#include <cmath>
#include <unordered_map>

#include "core/quadrature/TriangleRule.hpp"
#include "core/util/Errors.hpp"

namespace vorodg {
namespace {

struct CellSums {
  double l2 = 0, l2_exact = 0, energy = 0, energy_exact = 0;
};

/// Calls visit(at, w) for every error point of cell c: the 7-point rule on each sub-triangle of
/// the weight functions' lattice in each fan triangle, in one fixed order.
template <class Visit>
void for_each_error_point(const ElementTable& table, int c, Visit&& visit) {
  const PolygonMesh& mesh = table.mesh();
  const auto loop = mesh.cell_vertices(c);
  const int n = static_cast<int>(loop.size());
  const int m = table.lattice_size();
  const TriangleRule& rule = triangle_rule(7);
  const Point& C = table.centroid(c);
  for (int k = 0; k < n; ++k) {
    const double fan_area =
        0.5 * std::abs((mesh.vertex(loop[k]) - C).x() * (mesh.vertex(loop[(k + 1) % n]) - C).y() -
                       (mesh.vertex(loop[k]) - C).y() * (mesh.vertex(loop[(k + 1) % n]) - C).x());
    const double sub_area = fan_area / (m * m);
    for (int a = 0; a < m; ++a)
      for (int b = 0; a + b < m; ++b)
        for (bool up : {true, false}) {
          if (!up && a + b > m - 2) continue;
          for (int r = 0; r < rule.size(); ++r) {
            const double xi = rule.bary[r][1], eta = rule.bary[r][2];
            const double lu = up ? a + xi : a + 1 - xi, lv = up ? b + eta : b + 1 - eta;
            visit(FanPoint{k, Eigen::Vector3d(1 - (lu + lv) / m, lu / m, lv / m)},
                  rule.weights[r] * sub_area);
          }
        }
  }
}

/// A cell's error points (fan by fan) with their weights.
struct ErrorPoints {
  std::vector<FanPoint> at;
  std::vector<double> weight;
};

void collect_error_points(const ElementTable& table, int c, ErrorPoints& points) {
  points.at.clear(), points.weight.clear();
  for_each_error_point(table, c, [&](const FanPoint& at, double w) {
    points.at.push_back(at);
    points.weight.push_back(w);
  });
}

/// The shape functions at a cell's error points (point after point), as
/// ElementTable::evaluate_points gives them; kept for a class of congruent cells
/// (ElementTable::representative): evaluated once, read by every member.
struct ErrorPointShapes {
  std::vector<double> psi;
  std::vector<Eigen::Vector2d> grad;
};

void shapes_at(const ElementTable& table, int c, const ErrorPoints& points, ErrorPointShapes& s) {
  const std::size_t n = table.num_nodes(c);
  s.psi.resize(points.at.size() * n);
  s.grad.resize(points.at.size() * n);
  table.evaluate_points(c, points.at, s.psi.data(), s.grad.data());
}

ErrorPointShapes shapes_at_error_points(const ElementTable& table, int c) {
  ErrorPoints points;
  collect_error_points(table, c, points);
  ErrorPointShapes s;
  shapes_at(table, c, points, s);
  return s;
}

CellSums integrate_cell(const ElementTable& table, const ExactSolution& exact, int c,
                        const Eigen::VectorXd& u, bool energy,
                        const CellDilatationMean& dilatation_mean, const ErrorPointShapes* shared) {
  const bool mean_dilation = static_cast<bool>(dilatation_mean);
  const int n = table.num_nodes(c);
  const Eigen::Matrix3d& D = exact.material().D();
  thread_local ErrorPoints points;
  thread_local ErrorPointShapes own;
  collect_error_points(table, c, points);
  if (!shared) shapes_at(table, c, points, own);
  const ErrorPointShapes& shapes = shared ? *shared : own;
  CellSums sums;
  const double cell_dilatation = mean_dilation ? dilatation_mean(c, u) : 0.0;
  for (std::size_t p = 0; p < points.at.size(); ++p) {
    const double w = points.weight[p];
    const double* psi = &shapes.psi[p * n];
    const Eigen::Vector2d* grad = &shapes.grad[p * n];
    const Point x = table.position(c, points.at[p]);
    Eigen::Vector2d uh = Eigen::Vector2d::Zero();
    Eigen::Matrix2d Gh = Eigen::Matrix2d::Zero();
    for (int j = 0; j < n; ++j) {
      uh += psi[j] * u.segment<2>(2 * j);
      Gh += u.segment<2>(2 * j) * grad[j].transpose();
    }
    const Eigen::Vector2d ue = exact.displacement(x);
    sums.l2 += w * (uh - ue).squaredNorm();
    sums.l2_exact += w * ue.squaredNorm();
    if (!energy) continue;
    Eigen::Vector3d eh(Gh(0, 0), Gh(1, 1), Gh(0, 1) + Gh(1, 0));
    if (mean_dilation) {  // as the B-bar operator: half the gap to each normal strain
      const double shift = 0.5 * (cell_dilatation - (eh[0] + eh[1]));
      eh[0] += shift;
      eh[1] += shift;
    }
    const Eigen::Vector3d ee = exact.strain(x);
    sums.energy += w * (eh - ee).dot(D * (eh - ee));
    sums.energy_exact += w * ee.dot(D * ee);
  }
  return sums;
}

}  // namespace

ErrorReport compute_errors(const ElementTable& table, const ExactSolution& exact,
                           const std::function<Eigen::VectorXd(int)>& cell_dofs, bool energy,
                           int threads, const CellDilatationMean& dilatation_mean) {
  const PolygonMesh& mesh = table.mesh();
  const int nc = mesh.num_cells();
  std::vector<CellSums> sums(nc);
  std::unordered_map<int, ErrorPointShapes> shared;  // per class of congruent cells
  for (int c = 0; c < nc; ++c)
    if (table.representative(c) == c && table.class_size(c) > 1)
      shared.emplace(c, shapes_at_error_points(table, c));
#pragma omp parallel for schedule(dynamic, 128) num_threads(std::max(threads, 1))
  for (int c = 0; c < nc; ++c) {
    const auto found = shared.find(table.representative(c));
    sums[c] = integrate_cell(table, exact, c, cell_dofs(c), energy, dilatation_mean,
                             found == shared.end() ? nullptr : &found->second);
  }
  ErrorReport report;
  report.cell_l2_density.resize(nc);
  report.cell_energy_density.resize(nc);
  CellSums total;
  for (int c = 0; c < nc; ++c) {  // in cell order: the same sum for any thread count
    const double area = mesh.cell_area(c);
    total.l2 += sums[c].l2;
    total.l2_exact += sums[c].l2_exact;
    total.energy += sums[c].energy;
    total.energy_exact += sums[c].energy_exact;
    report.cell_l2_density[c] = sums[c].l2 / area;
    report.cell_energy_density[c] = sums[c].energy / area;
  }
  report.l2_absolute = std::sqrt(total.l2);
  report.energy_absolute = std::sqrt(total.energy);
  report.l2_error = total.l2_exact > 0 ? std::sqrt(total.l2 / total.l2_exact) : report.l2_absolute;
  report.energy_error = total.energy_exact > 0 ? std::sqrt(total.energy / total.energy_exact)
                                               : report.energy_absolute;
  if (!std::isfinite(report.l2_error) || !std::isfinite(report.energy_error))
    throw NumericalError("the error norms are not finite: the solution broke down");
  return report;
}

}  // namespace vorodg
