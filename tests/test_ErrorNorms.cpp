// Error norms (core/problem/ErrorNorms): relative L2 and energy errors of a DOF field against an
// exact solution.
// - The exact solution's own nodal interpolant on a triangle mesh (where the RK element is the
//   linear triangle) gives small, nonzero errors that agree with an independent computation of
//   the P1 interpolation error (collapsed Gauss-Legendre quadrature written here).
// - The nodal values of an affine field are reproduced: errors < 1e-13 on every family.
// - The interpolation error converges at the expected rates (2 in L2, 1 in energy).
// - The result does not depend on the thread count; the per-cell densities add up to the norms;
//   energy = false skips the energy error only.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <iostream>

#include "core/element/ElementTable.hpp"
#include "core/material/IsotropicElasticity.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/problem/AffineField.hpp"
#include "core/problem/ErrorNorms.hpp"
#include "core/problem/ManufacturedSolution.hpp"
#include "core/problem/TimoshenkoBeam.hpp"
#include "support/ElementTestMeshes.hpp"

namespace vorodg {
namespace {

using testing::Family;
using testing::kFamilies;
using testing::make_mesh;
using testing::mesh_of;
using testing::table_of;

// Nodal interpolant of `exact` as the cell DOF vector (u_x, u_y per vertex, loop order).
std::function<Eigen::VectorXd(int)> nodal_values(const PolygonMesh& mesh,
                                                 const ExactSolution& exact) {
  return [&mesh, &exact](int c) {
    const auto loop = mesh.cell_vertices(c);
    Eigen::VectorXd u(2 * loop.size());
    for (std::size_t k = 0; k < loop.size(); ++k)
      u.segment<2>(2 * k) = exact.displacement(mesh.vertex(loop[k]));
    return u;
  };
}

// Independent P1 interpolation error on a triangle mesh: 5 x 5 Gauss-Legendre on the square
// collapsed onto each triangle (exact for polynomials of degree 8 on the triangle).
struct IndependentErrors {
  double l2 = 0, l2_exact = 0, energy = 0, energy_exact = 0;
};

IndependentErrors p1_interpolation_errors(const PolygonMesh& mesh, const ExactSolution& exact) {
  static const std::array<double, 5> x = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                          0.5384693101056831, 0.9061798459386640};
  static const std::array<double, 5> w = {0.2369268850561891, 0.4786286704993665,
                                          0.5688888888888889, 0.4786286704993665,
                                          0.2369268850561891};
  const Eigen::Matrix3d& D = exact.material().D();
  IndependentErrors e;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto loop = mesh.cell_vertices(c);
    EXPECT_EQ(loop.size(), 3u);
    const Point p0 = mesh.vertex(loop[0]), p1 = mesh.vertex(loop[1]), p2 = mesh.vertex(loop[2]);
    const Eigen::Vector2d u0 = exact.displacement(p0), u1 = exact.displacement(p1),
                          u2 = exact.displacement(p2);
    Eigen::Matrix2d J;
    J << p1 - p0, p2 - p0;  // x = p0 + J (xi, eta)
    const double detJ = J.determinant();
    // Gradient of the interpolant: [u1 - u0, u2 - u0] J^-1.
    Eigen::Matrix2d dU;
    dU << u1 - u0, u2 - u0;
    const Eigen::Matrix2d Gh = dU * J.inverse();
    const Eigen::Vector3d eh(Gh(0, 0), Gh(1, 1), Gh(0, 1) + Gh(1, 0));
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < 5; ++j) {
        const double s = 0.5 * (1 + x[i]), t = 0.5 * (1 + x[j]);
        const double xi = s, eta = t * (1 - s);
        const double weight = 0.25 * w[i] * w[j] * (1 - s) * std::abs(detJ);
        const Point p = p0 + J * Eigen::Vector2d(xi, eta);
        const Eigen::Vector2d uh = (1 - xi - eta) * u0 + xi * u1 + eta * u2;
        const Eigen::Vector2d ue = exact.displacement(p);
        const Eigen::Vector3d ee = exact.strain(p);
        e.l2 += weight * (uh - ue).squaredNorm();
        e.l2_exact += weight * ue.squaredNorm();
        e.energy += weight * (eh - ee).dot(D * (eh - ee));
        e.energy_exact += weight * ee.dot(D * ee);
      }
  }
  return e;
}

TEST(ErrorNorms, InterpolantOnTrianglesMatchesIndependentP1Errors) {
  const Rectangle domain(0.0, -0.5, 4.0, 0.5);
  const PolygonMesh mesh = make_mesh(MeshFamily::tri, domain, 0.1, 5);
  const ElementTable table(mesh, ElementOptions{});
  const IsotropicElasticity material(1.0, 0.3, PlaneModel::stress);
  const TimoshenkoBeam beam(material, 4.0, 1.0, 1.0);
  const ErrorReport r = compute_errors(table, beam, nodal_values(mesh, beam));
  const IndependentErrors ref = p1_interpolation_errors(mesh, beam);
  const double l2_ref = std::sqrt(ref.l2 / ref.l2_exact),
               energy_ref = std::sqrt(ref.energy / ref.energy_exact);
  std::cout << "beam interpolant on tri (" << mesh.num_cells() << " cells, h_avg " << mesh.h_avg()
            << "): L2 " << r.l2_error << " (independent " << l2_ref << "), energy "
            << r.energy_error << " (independent " << energy_ref << ")\n";
  // Small but nonzero.
  EXPECT_GT(r.l2_error, 1e-6);
  EXPECT_LT(r.l2_error, 1e-2);
  EXPECT_GT(r.energy_error, 1e-4);
  EXPECT_LT(r.energy_error, 0.3);
  // The degree-5 rule is exact for the energy integrand (degree 4) and nearly so for the L2 one.
  EXPECT_NEAR(r.energy_error, energy_ref, 1e-9 * energy_ref);
  EXPECT_NEAR(r.energy_absolute, std::sqrt(ref.energy), 1e-9 * std::sqrt(ref.energy));
  EXPECT_NEAR(r.l2_error, l2_ref, 1e-4 * l2_ref);
  EXPECT_NEAR(r.l2_absolute, std::sqrt(ref.l2), 1e-4 * std::sqrt(ref.l2));
}

TEST(ErrorNorms, InterpolantErrorsConvergeAtTheExpectedRates) {
  const Rectangle domain(0.0, 0.0, 2.0, 1.0);
  const IsotropicElasticity material(1.0, 0.3, PlaneModel::stress);
  const ManufacturedSolution mms(material, domain);
  for (MeshFamily family : {MeshFamily::tri, MeshFamily::rcp}) {
    double h[2], l2[2], energy[2];
    for (int level = 0; level < 2; ++level) {
      const PolygonMesh mesh = make_mesh(family, domain, level == 0 ? 0.1 : 0.05, 5);
      const ElementTable table(mesh, ElementOptions{});
      const ErrorReport r = compute_errors(table, mms, nodal_values(mesh, mms));
      h[level] = mesh.h_avg();
      l2[level] = r.l2_error;
      energy[level] = r.energy_error;
    }
    const double rate_l2 = std::log(l2[0] / l2[1]) / std::log(h[0] / h[1]);
    const double rate_energy = std::log(energy[0] / energy[1]) / std::log(h[0] / h[1]);
    std::cout << "mms interpolant on " << family_name(family) << ": h " << h[0] << " -> " << h[1]
              << ", L2 " << l2[0] << " -> " << l2[1] << " (rate " << rate_l2 << "), energy "
              << energy[0] << " -> " << energy[1] << " (rate " << rate_energy << ")\n";
    EXPECT_GT(rate_l2, 1.7) << family_name(family);
    EXPECT_LT(rate_l2, 2.4) << family_name(family);
    EXPECT_GT(rate_energy, 0.8) << family_name(family);
    EXPECT_LT(rate_energy, 1.3) << family_name(family);
  }
}

class AffineNodalValues : public ::testing::TestWithParam<Family> {};

TEST_P(AffineNodalValues, AreReproducedExactly) {
  const Family& f = GetParam();
  const IsotropicElasticity material(1.0, 0.3, PlaneModel::stress);
  for (AffineField::Supports s : {AffineField::Supports::dirichlet, AffineField::Supports::mixed}) {
    const AffineField field(material, s);
    for (bool correction : {true, false}) {
      const ElementTable& table = table_of(f, 3, correction);
      const ErrorReport r = compute_errors(table, field, nodal_values(table.mesh(), field));
      EXPECT_LT(r.l2_error, 1e-13) << f.name << " correction " << correction;
      EXPECT_LT(r.energy_error, 1e-13) << f.name << " correction " << correction;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Families, AffineNodalValues, ::testing::ValuesIn(kFamilies),
                         [](const auto& info) {
                           std::string n = info.param.name;
                           for (char& ch : n)
                             if (ch == '-' || ch == '.') ch = '_';
                           return n;
                         });

TEST(ErrorNorms, IndependentOfThreadCount) {
  const IsotropicElasticity material(1.0, 0.3, PlaneModel::stress);
  const ManufacturedSolution mms(material, Rectangle(0.0, 0.0, 2.0, 1.0));
  for (const char* name : {"rcp", "perturbed-hex-0.3"}) {
    const Family* f = nullptr;
    for (const Family& g : kFamilies)
      if (std::string(g.name) == name) f = &g;
    ASSERT_NE(f, nullptr);
    const ElementTable& table = table_of(*f, 3, true);
    const auto dofs = nodal_values(table.mesh(), mms);
    const ErrorReport one = compute_errors(table, mms, dofs, true, 1);
    const ErrorReport two = compute_errors(table, mms, dofs, true, 2);
    EXPECT_EQ(one.l2_error, two.l2_error) << name;
    EXPECT_EQ(one.energy_error, two.energy_error) << name;
    EXPECT_EQ(one.l2_absolute, two.l2_absolute) << name;
    EXPECT_EQ(one.energy_absolute, two.energy_absolute) << name;
    EXPECT_EQ(one.cell_l2_density, two.cell_l2_density) << name;
    EXPECT_EQ(one.cell_energy_density, two.cell_energy_density) << name;
  }
}

TEST(ErrorNorms, DensitiesAddUpAndEnergyCanBeSkipped) {
  const Family& f = kFamilies[0];  // rcp
  const ElementTable& table = table_of(f, 3, true);
  const PolygonMesh& mesh = table.mesh();
  const IsotropicElasticity material(1.0, 0.3, PlaneModel::strain);
  const ManufacturedSolution mms(material, mesh.domain());
  const auto dofs = nodal_values(mesh, mms);
  const ErrorReport r = compute_errors(table, mms, dofs);
  ASSERT_EQ(static_cast<int>(r.cell_l2_density.size()), mesh.num_cells());
  ASSERT_EQ(static_cast<int>(r.cell_energy_density.size()), mesh.num_cells());
  double l2 = 0, energy = 0;
  for (int c = 0; c < mesh.num_cells(); ++c) {
    EXPECT_GE(r.cell_l2_density[c], 0.0);
    EXPECT_GE(r.cell_energy_density[c], 0.0);
    l2 += r.cell_l2_density[c] * mesh.cell_area(c);
    energy += r.cell_energy_density[c] * mesh.cell_area(c);
  }
  EXPECT_NEAR(std::sqrt(l2), r.l2_absolute, 1e-12 * r.l2_absolute);
  EXPECT_NEAR(std::sqrt(energy), r.energy_absolute, 1e-12 * r.energy_absolute);
  EXPECT_GT(r.l2_error, 0.0);
  EXPECT_GT(r.energy_error, r.l2_error);  // one order of h less

  const ErrorReport no_energy = compute_errors(table, mms, dofs, false);
  EXPECT_EQ(no_energy.l2_error, r.l2_error);
  EXPECT_EQ(no_energy.energy_error, 0.0);

  // The zero field has relative errors of exactly 1.
  const auto zero = [&](int c) { return Eigen::VectorXd::Zero(2 * mesh.cell_size(c)).eval(); };
  const ErrorReport z = compute_errors(table, mms, zero);
  EXPECT_NEAR(z.l2_error, 1.0, 1e-14);
  EXPECT_NEAR(z.energy_error, 1.0, 1e-14);
}

}  // namespace
}  // namespace vorodg
