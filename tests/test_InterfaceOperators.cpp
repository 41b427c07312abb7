// The DG interface operators (interfaces/InterfaceOperators), docs/design.md "Discontinuous
// Galerkin":
// - dofs(f): cell 1's DOFs then cell 2's, contiguous, in each cell's loop order.
// - jump(f, t) [u] = u_1 - u_2 at a + t (b - a): zero for a continuous (CG-like) field at any t;
//   for a field that is u on cell 1 and 0 on cell 2 it equals u there (and -u the other way);
//   mean_jump = jump(0.5).
// - mean_traction: {sigma_mean(u)} n = (sigma_mean,1 + sigma_mean,2) / 2 n with n cell 1's normal;
//   for the DOFs of an affine field it equals sigma n exactly; for any field it agrees with the
//   integrator's mean stress (an independent path).
// - point_traction(f, t): for an affine field sigma n (to 1e-9: the edge-limit gradients are
//   less well conditioned than interior ones); for a general (discontinuous)
//   field the average of the two cells' own stresses at the physical point a + t (b - a),
//   evaluated here independently (searching each cell's fan triangle that holds the edge).
// - mean_stress_operator(c) u_c = the integrator's mean_stress(c, u_c).
// On every test mesh family (corrected tables, 3-point rule).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "core/element/ElasticityIntegrator.hpp"
#include "core/problem/AffineField.hpp"
#include "interfaces/DgSpace.hpp"
#include "interfaces/InterfaceOperators.hpp"
#include "support/ElementTestMeshes.hpp"

namespace vorodg {
namespace {

using testing::Family;
using testing::kFamilies;
using testing::table_of;
using testing::test_name;

constexpr double kPoints[] = {0.0, 0.2113248654051871, 0.5, 0.7886751345948129, 1.0};
constexpr double kInterior[] = {0.2113248654051871, 0.5, 0.7886751345948129};

/// A smooth non-polynomial field.
Eigen::Vector2d wavy(const Point& x) {
  return {std::sin(1.3 * x.x() + 0.4) * std::cos(2.1 * x.y()) + 0.3 * x.x() * x.y(),
          std::cos(0.7 * x.x() - 1.1 * x.y()) + 0.2 * x.y() * x.y()};
}

/// DOFs of cell c interpolating `field` at its vertices (loop order).
template <class Field>
Eigen::VectorXd cell_values(const PolygonMesh& mesh, int c, const Field& field) {
  const auto loop = mesh.cell_vertices(c);
  Eigen::VectorXd u(2 * loop.size());
  for (std::size_t k = 0; k < loop.size(); ++k) u.segment<2>(2 * k) = field(mesh.vertex(loop[k]));
  return u;
}

/// A discontinuous field: a different value for each cell's copy of each vertex.
Eigen::VectorXd broken_values(const PolygonMesh& mesh, int c) {
  Eigen::VectorXd u = cell_values(mesh, c, wavy);
  for (int i = 0; i < u.size(); ++i) u[i] += 0.1 * std::sin(3.7 * c + 1.9 * i + 0.5);
  return u;
}

Eigen::Matrix<double, 2, 3> traction_map(const Eigen::Vector2d& n) {
  Eigen::Matrix<double, 2, 3> N;
  N << n.x(), 0.0, n.y(), 0.0, n.y(), n.x();
  return N;
}

class InterfaceOperatorsFamilies : public ::testing::TestWithParam<Family> {
 protected:
  InterfaceOperatorsFamilies()
      : table_(table_of(GetParam(), 3, true)),
        mesh_(table_.mesh()),
        material_(1.0, 0.3, PlaneModel::stress),
        integrator_(table_, material_, false),
        space_(mesh_),
        ops_(space_, integrator_, table_) {}

  /// The interface's two cells' DOFs stacked as the operators expect.
  static Eigen::VectorXd stack(const Eigen::VectorXd& u1, const Eigen::VectorXd& u2) {
    Eigen::VectorXd u(u1.size() + u2.size());
    u << u1, u2;
    return u;
  }

  const ElementTable& table_;
  const PolygonMesh& mesh_;
  IsotropicElasticity material_;
  ElasticityIntegrator integrator_;
  DgSpace space_;
  InterfaceOperators ops_;
};

TEST_P(InterfaceOperatorsFamilies, DofsAreCellOneThenCellTwo) {
  for (const Interface& f : space_.interfaces()) {
    const std::vector<int> dofs = ops_.dofs(f);
    const int m1 = space_.cell_dof_count(f.cell[0]), m2 = space_.cell_dof_count(f.cell[1]);
    ASSERT_EQ(static_cast<int>(dofs.size()), m1 + m2);
    for (int i = 0; i < m1; ++i) EXPECT_EQ(dofs[i], space_.dof(f.cell[0], 0) + i);
    for (int i = 0; i < m2; ++i) EXPECT_EQ(dofs[m1 + i], space_.dof(f.cell[1], 0) + i);
    const InterfaceOperator J = ops_.jump(f, 0.3);
    EXPECT_EQ(J.rows(), 2);
    EXPECT_EQ(J.cols(), m1 + m2);
    EXPECT_EQ(ops_.mean_traction(f).cols(), m1 + m2);
    EXPECT_EQ(ops_.point_traction(f, 0.3).cols(), m1 + m2);
  }
}

TEST_P(InterfaceOperatorsFamilies, JumpOfAContinuousFieldIsZero) {
  double worst = 0.0;
  for (const Interface& f : space_.interfaces()) {
    const Eigen::VectorXd u =
        stack(cell_values(mesh_, f.cell[0], wavy), cell_values(mesh_, f.cell[1], wavy));
    for (double t : kPoints) worst = std::max(worst, (ops_.jump(f, t) * u).norm());
    worst = std::max(worst, (ops_.mean_jump(f) * u).norm());
  }
  EXPECT_LT(worst, 1e-15);
}

TEST_P(InterfaceOperatorsFamilies, JumpOfAOneSidedFieldIsTheField) {
  const AffineField field(material_, AffineField::Supports::dirichlet);
  const auto affine = [&](const Point& x) { return field.displacement(x); };
  double worst = 0.0;
  for (const Interface& f : space_.interfaces()) {
    const Eigen::VectorXd u1 = cell_values(mesh_, f.cell[0], affine);
    const Eigen::VectorXd u2 = cell_values(mesh_, f.cell[1], affine);
    const Eigen::VectorXd only1 = stack(u1, Eigen::VectorXd::Zero(u2.size()));
    const Eigen::VectorXd only2 = stack(Eigen::VectorXd::Zero(u1.size()), u2);
    for (double t : kPoints) {
      const Eigen::Vector2d expected = field.displacement(f.a + t * (f.b - f.a));
      worst = std::max(worst, (ops_.jump(f, t) * only1 - expected).norm());
      worst = std::max(worst, (ops_.jump(f, t) * only2 + expected).norm());
    }
    // The midpoint jump is the edge mean of a linear jump.
    EXPECT_EQ(ops_.mean_jump(f), ops_.jump(f, 0.5)) << "edge " << f.edge;
    // Only the copies of the edge's two end vertices enter.
    const InterfaceOperator J = ops_.jump(f, 0.3);
    const int m1 = space_.cell_dof_count(f.cell[0]);
    const int o1 = space_.dof(f.cell[0], 0), o2 = space_.dof(f.cell[1], 0);
    const int nonzero_columns[] = {f.dof_v0[0] - o1,      f.dof_v0[0] - o1 + 1,
                                   f.dof_v1[0] - o1,      f.dof_v1[0] - o1 + 1,
                                   m1 + f.dof_v0[1] - o2, m1 + f.dof_v0[1] - o2 + 1,
                                   m1 + f.dof_v1[1] - o2, m1 + f.dof_v1[1] - o2 + 1};
    InterfaceOperator rest = J;
    for (int col : nonzero_columns) rest.col(col).setZero();
    EXPECT_EQ(rest.cwiseAbs().maxCoeff(), 0.0) << "edge " << f.edge;
  }
  EXPECT_LT(worst, 1e-15);
}

TEST_P(InterfaceOperatorsFamilies, MeanTractionOfAnAffineFieldIsSigmaN) {
  const AffineField field(material_, AffineField::Supports::dirichlet);
  const auto affine = [&](const Point& x) { return field.displacement(x); };
  const Eigen::Vector3d sigma = field.stress(Point(0.3, 0.4));
  double worst = 0.0;
  for (const Interface& f : space_.interfaces()) {
    const Eigen::VectorXd u =
        stack(cell_values(mesh_, f.cell[0], affine), cell_values(mesh_, f.cell[1], affine));
    const Eigen::Vector2d expected = traction_map(f.normal) * sigma;
    worst = std::max(worst, (ops_.mean_traction(f) * u - expected).norm() / sigma.norm());
  }
  std::cout << GetParam().name << ": mean traction of the affine field, worst relative error "
            << worst << "\n";
  EXPECT_LT(worst, 1e-10);
}

TEST_P(InterfaceOperatorsFamilies, PointTractionOfAnAffineFieldIsSigmaN) {
  const AffineField field(material_, AffineField::Supports::dirichlet);
  const auto affine = [&](const Point& x) { return field.displacement(x); };
  const Eigen::Vector3d sigma = field.stress(Point(0.3, 0.4));
  double worst = 0.0;
  for (const Interface& f : space_.interfaces()) {
    const Eigen::VectorXd u =
        stack(cell_values(mesh_, f.cell[0], affine), cell_values(mesh_, f.cell[1], affine));
    const Eigen::Vector2d expected = traction_map(f.normal) * sigma;
    for (double t : kInterior)
      worst = std::max(worst, (ops_.point_traction(f, t) * u - expected).norm() / sigma.norm());
  }
  std::cout << GetParam().name << ": point traction of the affine field, worst relative error "
            << worst << "\n";
  // The one-sided gradients at an edge point are the exact edge limit of the RK functions and
  // are less well conditioned than at interior points (observed: a 3e-17 change of the
  // barycentric coordinates moves them by ~3e-11, and the affine error reaches ~8e-11), hence
  // 1e-9 here against 1e-10 for the mean traction.
  EXPECT_LT(worst, 1e-9);
}

TEST_P(InterfaceOperatorsFamilies, MeanTractionAgreesWithTheIntegratorsMeanStress) {
  double worst = 0.0, size = 0.0;
  for (int c = 0; c < mesh_.num_cells(); ++c) {
    const Eigen::VectorXd u = broken_values(mesh_, c);
    const Eigen::Vector3d mean = integrator_.mean_stress(c, u);
    worst = std::max(worst, (ops_.mean_stress_operator(c) * u - mean).norm());
    size = std::max(size, mean.norm());
  }
  EXPECT_LT(worst, 1e-12 * size) << "mean_stress_operator vs ElasticityIntegrator::mean_stress";
  worst = 0.0;
  for (const Interface& f : space_.interfaces()) {
    const Eigen::VectorXd u1 = broken_values(mesh_, f.cell[0]),
                          u2 = broken_values(mesh_, f.cell[1]);
    const Eigen::Vector2d expected =
        0.5 * traction_map(f.normal) *
        (integrator_.mean_stress(f.cell[0], u1) + integrator_.mean_stress(f.cell[1], u2));
    worst = std::max(worst, (ops_.mean_traction(f) * stack(u1, u2) - expected).norm());
  }
  EXPECT_LT(worst, 1e-12 * size);
}

/// Cell c's own stress (uncorrected shape-function gradients) at the point a + t (b - a) of the
/// interface's edge, found independently: the fan triangle (centroid, v_k, v_k+1) whose outer
/// side is the edge, with barycentric coordinates of the point.
Eigen::Vector3d own_stress_at(const ElementTable& table, const Eigen::Matrix3d& D,
                              const Interface& f, int c, double t, const Eigen::VectorXd& u) {
  const PolygonMesh& mesh = table.mesh();
  const MeshEdge& e = mesh.edge(f.edge);
  const auto loop = mesh.cell_vertices(c);
  const int n = static_cast<int>(loop.size());
  FanPoint at{-1, Eigen::Vector3d::Zero()};
  for (int k = 0; k < n; ++k) {
    const int p = loop[k], q = loop[(k + 1) % n];
    if (p == e.v0 && q == e.v1) at = FanPoint{k, Eigen::Vector3d(0.0, 1.0 - t, t)};
    if (p == e.v1 && q == e.v0) at = FanPoint{k, Eigen::Vector3d(0.0, t, 1.0 - t)};
  }
  EXPECT_GE(at.fan, 0) << "edge " << f.edge << " not found in cell " << c;
  if (at.fan < 0) return Eigen::Vector3d::Zero();
  const Point x = f.a + t * (f.b - f.a);
  EXPECT_LT((table.position(c, at) - x).norm(), 1e-14) << "edge " << f.edge << " cell " << c;
  std::vector<double> psi(n);
  std::vector<Eigen::Vector2d> grad(n);
  table.evaluate(c, at, psi.data(), grad.data());
  Eigen::Vector3d strain = Eigen::Vector3d::Zero();
  for (int k = 0; k < n; ++k) {
    strain[0] += grad[k].x() * u[2 * k];
    strain[1] += grad[k].y() * u[2 * k + 1];
    strain[2] += grad[k].y() * u[2 * k] + grad[k].x() * u[2 * k + 1];
  }
  return D * strain;
}

TEST_P(InterfaceOperatorsFamilies, PointTractionAveragesTheOneSidedStressesAtThePoint) {
  double worst = 0.0, size = 0.0;
  const Eigen::Matrix3d& D = material_.D();
  for (const Interface& f : space_.interfaces()) {
    const Eigen::VectorXd u1 = broken_values(mesh_, f.cell[0]),
                          u2 = broken_values(mesh_, f.cell[1]);
    for (double t : kInterior) {
      const Eigen::Vector3d s1 = own_stress_at(table_, D, f, f.cell[0], t, u1);
      const Eigen::Vector3d s2 = own_stress_at(table_, D, f, f.cell[1], t, u2);
      const Eigen::Vector2d expected = 0.5 * traction_map(f.normal) * (s1 + s2);
      worst = std::max(worst, (ops_.point_traction(f, t) * stack(u1, u2) - expected).norm());
      size = std::max(size, expected.norm());
    }
  }
  std::cout << GetParam().name << ": point traction vs independent one-sided stresses, worst "
            << worst << " (size " << size << ")\n";
  EXPECT_LT(worst, 1e-9 * size);  // the conditioning of the edge gradients, see above
}

INSTANTIATE_TEST_SUITE_P(Families, InterfaceOperatorsFamilies, ::testing::ValuesIn(kFamilies),
                         [](const auto& info) { return test_name(info.param.name); });

}  // namespace
}  // namespace vorodg
