// Continuous Galerkin elasticity (cg/CgElasticity) end to end, docs/design.md "Continuous
// Galerkin" and "Verification problems and error norms":
// 1. Patch tests (patch, patch-mixed): with the divergence correction the affine field is
//    reproduced to 1e-10 (L2, energy, nodal) on rcp, hex, perturbed-hex (r = 0.4), tri and quad;
//    without it the test fails on rcp and perturbed hexagons (errors printed).
// 2. On triangles the CG solution equals an independent linear-triangle (P1) solution written
//    here (beam and patch-mixed), to 1e-10 relative.
// 3. Beam convergence, L/D = 8/sqrt(3), five levels on hex and perturbed-hex (r = 0.3): with the
//    correction L2 rate >= 1.8, energy rate >= 0.9 (least-squares slopes); without it the
//    rates and errors are printed.
// 4. Plane strain near incompressibility: mean dilation keeps the error near the nu = 0.3 one,
//    the standard operator locks.
// 5. Threads: bitwise identical displacements for 1 and 2 threads.
// Plus: the singular problem is refused, Dirichlet values are imposed exactly, the manufactured
// solution (body force) converges, cell_dofs gathers the vertex values, stage times are kept.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <vector>

#include "cg/CgElasticity.hpp"
#include "core/element/ElasticityIntegrator.hpp"
#include "core/element/ElementTable.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/problem/AffineField.hpp"
#include "core/problem/ErrorNorms.hpp"
#include "core/problem/ManufacturedSolution.hpp"
#include "core/problem/TimoshenkoBeam.hpp"
#include "core/util/Errors.hpp"
#include "support/ElementTestMeshes.hpp"
#include "verification/report/RateFit.hpp"
#include "verification/solve/SolveRun.hpp"

namespace vorodg {
namespace {

using testing::Family;
using testing::kFamilies;
using testing::make_mesh;
using testing::table_of;
using testing::test_name;

constexpr double kBeamL = 4.618802153517006;  // L/D = 8/sqrt(3)

struct CgRun {
  Eigen::Matrix2Xd u;
  ErrorReport errors;
  double nodal_error = 0.0;  // max |u_h - u| / max |u| over the vertices
  double rcond = 0.0;
};

CgRun solve_cg(const ElementTable& table, const ExactSolution& problem, bool mean_dilation = false,
               int threads = 1) {
  const ElasticityIntegrator integrator(table, problem.material(), mean_dilation);
  CgElasticity cg(table, integrator, problem, threads);
  cg.run();
  CgRun r;
  r.u = cg.vertex_displacement();
  r.rcond = cg.factorization().rcond;
  r.errors = compute_errors(table, problem, [&](int c) { return cg.cell_dofs(c); });
  const PolygonMesh& mesh = table.mesh();
  double diff = 0, size = 0;
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const Eigen::Vector2d ue = problem.displacement(mesh.vertex(v));
    diff = std::max(diff, (r.u.col(v) - ue).norm());
    size = std::max(size, ue.norm());
  }
  r.nodal_error = diff / size;
  return r;
}

const Family& family_named(const std::string& name) {
  for (const Family& f : kFamilies)
    if (name == f.name) return f;
  throw std::logic_error("no test family " + name);
}

// ------------------------------------------------------------------------------------------
// 1. Patch tests
// ------------------------------------------------------------------------------------------

struct PatchCase {
  const char* family;
  AffineField::Supports supports;
};

std::string supports_name(AffineField::Supports s) {
  return s == AffineField::Supports::dirichlet ? "patch" : "patch_mixed";
}

class PatchTest : public ::testing::TestWithParam<PatchCase> {};

TEST_P(PatchTest, PassesWithTheCorrection) {
  const PatchCase& p = GetParam();
  const IsotropicElasticity material(1.0, 0.3, PlaneModel::stress);
  const AffineField field(material, p.supports);
  const ElementTable& table = table_of(family_named(p.family), 3, true);
  const CgRun r = solve_cg(table, field);
  std::cout << p.family << " " << field.name() << " corrected: L2 " << r.errors.l2_error
            << ", energy " << r.errors.energy_error << ", nodal " << r.nodal_error << "\n";
  EXPECT_LT(r.errors.l2_error, 1e-10);
  EXPECT_LT(r.errors.energy_error, 1e-10);
  EXPECT_LT(r.nodal_error, 1e-10);
  EXPECT_GT(r.rcond, 0.0);
  EXPECT_LE(r.rcond, 1.0);
}

TEST_P(PatchTest, PassesWithMeanDilationInPlaneStrain) {
  const PatchCase& p = GetParam();
  const IsotropicElasticity material(1.0, 0.4999, PlaneModel::strain);
  const AffineField field(material, p.supports);
  const ElementTable& table = table_of(family_named(p.family), 3, true);
  const CgRun r = solve_cg(table, field, /*mean_dilation=*/true);
  EXPECT_LT(r.errors.l2_error, 1e-10);
  EXPECT_LT(r.errors.energy_error, 1e-10);
  EXPECT_LT(r.nodal_error, 1e-10);
}

TEST_P(PatchTest, WithoutTheCorrection) {
  const PatchCase& p = GetParam();
  const IsotropicElasticity material(1.0, 0.3, PlaneModel::stress);
  const AffineField field(material, p.supports);
  const ElementTable& table = table_of(family_named(p.family), 3, false);
  const CgRun r = solve_cg(table, field);
  std::cout << "UNCORRECTED " << p.family << " " << field.name() << ": L2 " << r.errors.l2_error
            << ", energy " << r.errors.energy_error << ", nodal " << r.nodal_error << "\n";
  const std::string f = p.family;
  if (f == "rcp" || f.starts_with("perturbed-hex")) {
    // The discrete divergence identity fails: the patch test fails.
    EXPECT_GT(r.errors.l2_error, 1e-6);
    EXPECT_GT(r.errors.energy_error, 1e-6);
    EXPECT_GT(r.nodal_error, 1e-6);
  } else if (f == "tri") {
    // Linear triangles satisfy it without help.
    EXPECT_LT(r.errors.l2_error, 1e-10);
    EXPECT_LT(r.errors.energy_error, 1e-10);
  }
}

std::vector<PatchCase> patch_cases() {
  std::vector<PatchCase> cases;
  for (const char* f : {"rcp", "hex", "perturbed-hex-0.3", "perturbed-hex-0.4", "tri", "quad"})
    for (auto s : {AffineField::Supports::dirichlet, AffineField::Supports::mixed})
      cases.push_back({f, s});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Families, PatchTest, ::testing::ValuesIn(patch_cases()),
                         [](const auto& info) {
                           return test_name(std::string(info.param.family) + "_" +
                                            supports_name(info.param.supports));
                         });

TEST(CgElasticity, RefusesAProblemWithoutDirichletData) {
  const IsotropicElasticity material(1.0, 0.3, PlaneModel::stress);
  const AffineField field(material, AffineField::Supports::traction);
  const ElementTable& table = table_of(family_named("hex"), 3, true);
  const ElasticityIntegrator integrator(table, material, false);
  CgElasticity cg(table, integrator, field);
  EXPECT_THROW(cg.run(), InputError);
}

// ------------------------------------------------------------------------------------------
// 2. Independent linear-triangle solution
// ------------------------------------------------------------------------------------------

// Standard P1 elasticity on the triangles of `mesh`: constant-strain element stiffness
// area * B^T D B, prescribed displacements at the vertices on Dirichlet sides (found
// geometrically), tractions on boundary edges (found as edges of one triangle) integrated
// against the linear shape functions with two-point Gauss. Returns the vertex displacements.
Eigen::Matrix2Xd p1_solution(const PolygonMesh& mesh, const ExactSolution& problem) {
  const int nv = mesh.num_vertices(), n = 2 * nv;
  const Rectangle& dom = mesh.domain();
  const double tol = 1e-9 * dom.scale();
  const Eigen::Matrix3d& D = problem.material().D();
  auto on_side = [&](const Point& p, Side s) {
    switch (s) {
      case Side::left: return std::abs(p.x() - dom.x0()) < tol;
      case Side::right: return std::abs(p.x() - dom.x1()) < tol;
      case Side::bottom: return std::abs(p.y() - dom.y0()) < tol;
      case Side::top: return std::abs(p.y() - dom.y1()) < tol;
      default: return false;
    }
  };
  const Side sides[] = {Side::left, Side::right, Side::bottom, Side::top};

  // Dirichlet vertices.
  std::vector<char> fixed(n, 0);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
  for (int v = 0; v < nv; ++v)
    for (Side s : sides)
      if (problem.boundary(s) == BoundaryKind::dirichlet && on_side(mesh.vertex(v), s)) {
        fixed[2 * v] = fixed[2 * v + 1] = 1;
        u.segment<2>(2 * v) = problem.dirichlet_value(mesh.vertex(v));
      }

  // Global stiffness (full) and load.
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  std::map<std::pair<int, int>, int> edge_count;  // sorted vertex pair -> number of triangles
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto t = mesh.cell_vertices(c);
    EXPECT_EQ(t.size(), 3u) << "cell " << c << " is not a triangle";
    const Point p[3] = {mesh.vertex(t[0]), mesh.vertex(t[1]), mesh.vertex(t[2])};
    const double area2 =
        (p[1] - p[0]).x() * (p[2] - p[0]).y() - (p[1] - p[0]).y() * (p[2] - p[0]).x();
    EXPECT_GT(area2, 0.0) << "cell " << c;
    Eigen::Matrix<double, 3, 6> B = Eigen::Matrix<double, 3, 6>::Zero();
    for (int i = 0; i < 3; ++i) {
      const Point& pj = p[(i + 1) % 3];
      const Point& pk = p[(i + 2) % 3];
      const double b = (pj.y() - pk.y()) / area2,
                   cc = (pk.x() - pj.x()) / area2;  // d lambda_i / dx, dy
      B(0, 2 * i) = b;
      B(1, 2 * i + 1) = cc;
      B(2, 2 * i) = cc;
      B(2, 2 * i + 1) = b;
    }
    const Eigen::Matrix<double, 6, 6> Ke = 0.5 * area2 * B.transpose() * D * B;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        triplets.emplace_back(2 * t[i / 2] + i % 2, 2 * t[j / 2] + j % 2, Ke(i, j));
    // Body force: zero for the problems compared here (up to rounding in -div sigma).
    const Point centroid = (p[0] + p[1] + p[2]) / 3;
    EXPECT_LT(problem.body_force(centroid).norm(), 1e-12 * (1 + problem.stress(centroid).norm()));
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      edge_count[{std::min(a, b), std::max(a, b)}] += 1;
    }
  }
  // Boundary edges: traversed once, counter-clockwise by their triangle.
  for (int c = 0; c < mesh.num_cells(); ++c) {
    const auto t = mesh.cell_vertices(c);
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (edge_count[{std::min(a, b), std::max(a, b)}] != 1) continue;
      const Point pa = mesh.vertex(a), pb = mesh.vertex(b);
      Side side = Side::none;
      for (Side s : sides)
        if (on_side(pa, s) && on_side(pb, s)) side = s;
      EXPECT_NE(side, Side::none) << "boundary edge " << a << "-" << b << " on no side";
      if (side == Side::none || problem.boundary(side) != BoundaryKind::traction) continue;
      const Eigen::Vector2d tangent = pb - pa;
      const double length = tangent.norm();
      const Eigen::Vector2d normal(tangent.y() / length, -tangent.x() / length);
      const double g = 0.5 / std::sqrt(3.0);
      for (double s : {0.5 - g, 0.5 + g}) {
        const Eigen::Vector2d tr = problem.traction(pa + s * tangent, normal);
        f.segment<2>(2 * a) += 0.5 * length * (1 - s) * tr;
        f.segment<2>(2 * b) += 0.5 * length * s * tr;
      }
    }
  }
  Eigen::SparseMatrix<double> K(n, n);
  K.setFromTriplets(triplets.begin(), triplets.end());

  // Eliminate the Dirichlet DOFs.
  std::vector<int> index(n, -1), free;
  for (int d = 0; d < n; ++d)
    if (!fixed[d]) {
      index[d] = static_cast<int>(free.size());
      free.push_back(d);
    }
  const Eigen::VectorXd Ku = K * u;  // u holds the prescribed values, zero elsewhere
  std::vector<Eigen::Triplet<double>> ff;
  for (int k = 0; k < K.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, k); it; ++it)
      if (index[it.row()] >= 0 && index[it.col()] >= 0)
        ff.emplace_back(index[it.row()], index[it.col()], it.value());
  const int nf = static_cast<int>(free.size());
  Eigen::SparseMatrix<double> Kff(nf, nf);
  Kff.setFromTriplets(ff.begin(), ff.end());
  Eigen::VectorXd rhs(nf);
  for (int k = 0; k < nf; ++k) rhs[k] = f[free[k]] - Ku[free[k]];
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(Kff);
  EXPECT_EQ(ldlt.info(), Eigen::Success);
  const Eigen::VectorXd x = ldlt.solve(rhs);
  for (int k = 0; k < nf; ++k) u[free[k]] = x[k];
  return Eigen::Map<const Eigen::Matrix2Xd>(u.data(), 2, nv);
}

double relative_max_difference(const Eigen::Matrix2Xd& a, const Eigen::Matrix2Xd& b) {
  return (a - b).colwise().norm().maxCoeff() / b.colwise().norm().maxCoeff();
}

class TriangleEquivalence : public ::testing::Test {
 protected:
  static const PolygonMesh& mesh() {
    static const PolygonMesh m =
        make_mesh(MeshFamily::tri, Rectangle(0.0, -0.5, 4.0, 0.5), 0.1, 11);
    return m;
  }
  void compare(const ExactSolution& problem, const ElementOptions& options) {
    const ElementTable table(mesh(), options);
    const CgRun cg = solve_cg(table, problem);
    const Eigen::Matrix2Xd p1 = p1_solution(mesh(), problem);
    const double diff = relative_max_difference(cg.u, p1);
    std::cout << problem.name() << " on " << mesh().num_cells() << " triangles (rule "
              << options.rule_points << ", correction " << options.divergence_correction
              << "): CG vs independent P1, max relative difference " << diff << " (L2 error "
              << cg.errors.l2_error << ")\n";
    EXPECT_LT(diff, 1e-10);
  }
};

TEST_F(TriangleEquivalence, Beam) {
  for (PlaneModel plane : {PlaneModel::stress, PlaneModel::strain}) {
    const IsotropicElasticity material(1.0, 0.3, plane);
    const TimoshenkoBeam beam(material, 4.0, 1.0, 1.0);
    compare(beam, ElementOptions{});
  }
}

TEST_F(TriangleEquivalence, PatchMixed) {
  const IsotropicElasticity material(1.0, 0.3, PlaneModel::stress);
  const AffineField field(material, AffineField::Supports::mixed);
  compare(field, ElementOptions{});
}

TEST_F(TriangleEquivalence, BeamWithOtherRulesAndWithoutCorrection) {
  const IsotropicElasticity material(1.0, 0.3, PlaneModel::stress);
  const TimoshenkoBeam beam(material, 4.0, 1.0, 1.0);
  ElementOptions o;
  o.rule_points = 1;
  compare(beam, o);
  o.rule_points = 6;
  o.divergence_correction = false;
  compare(beam, o);
}

// ------------------------------------------------------------------------------------------
// 3. Beam convergence (hex and perturbed hex, with and without the correction)
// ------------------------------------------------------------------------------------------

// The rate every report uses (verification/report/RateFit).
double least_squares_slope(const std::vector<double>& h, const std::vector<double>& e) {
  return fit_rate(h, e).rate;
}

struct BeamSeries {
  std::vector<double> h, l2, energy;
  std::vector<int> cells;
};

// One mesh family's levels, with the divergence correction on or off, printed with its rates.
BeamSeries beam_series(MeshFamily family, bool correction) {
  const Rectangle domain(0.0, -0.5, kBeamL, 0.5);
  SolveSettings settings;
  settings.problem = "beam";
  settings.plane = PlaneModel::stress;
  settings.E = 1.0;
  settings.nu = 0.3;
  settings.load = 1.0;
  settings.element.divergence_correction = correction;
  BeamSeries s;
  for (double h : {0.2, 0.1, 0.05, 0.025, 0.0125}) {
    const PolygonMesh mesh = make_mesh(family, domain, h, /*seed=*/2024, /*r=*/0.3);
    const SolveResult r = run_solve(mesh, settings);
    s.h.push_back(mesh.h_avg());
    s.l2.push_back(r.l2_error);
    s.energy.push_back(r.energy_error);
    s.cells.push_back(mesh.num_cells());
  }
  std::cout << "beam, L/D = 8/sqrt(3), plane stress, nu = 0.3, " << family_name(family)
            << (correction ? ", corrected" : ", UNCORRECTED") << ": L2 rate "
            << least_squares_slope(s.h, s.l2) << ", energy rate "
            << least_squares_slope(s.h, s.energy) << "\n";
  for (std::size_t i = 0; i < s.h.size(); ++i) {
    std::cout << "    cells " << std::setw(6) << s.cells[i] << "  h_avg " << std::setw(10) << s.h[i]
              << "  L2 " << std::setw(11) << s.l2[i] << "  energy " << std::setw(11) << s.energy[i];
    if (i > 0)
      std::cout << "  (pairwise L2 rate " << pair_rate(s.h[i - 1], s.l2[i - 1], s.h[i], s.l2[i])
                << ", energy " << pair_rate(s.h[i - 1], s.energy[i - 1], s.h[i], s.energy[i])
                << ")";
    std::cout << "\n";
  }
  return s;
}

// The corrected element converges at rates 2 and 1 on the family's levels.
void expect_corrected_rates(const BeamSeries& s, MeshFamily family) {
  const std::string_view name = family_name(family);
  EXPECT_GE(least_squares_slope(s.h, s.l2), 1.8) << name << " corrected L2 rate";
  EXPECT_GE(least_squares_slope(s.h, s.energy), 0.9) << name << " corrected energy rate";
}

// One test per mesh family, so that the two (the suite's longest) run side by side. Plain
// tests, not parameterized ones: ctest records the cost of a test only under a name without
// spaces, and orders the next run by it.
TEST(CgElasticity, BeamConvergenceOnHex) {
  expect_corrected_rates(beam_series(MeshFamily::hex, true), MeshFamily::hex);
}

TEST(CgElasticity, BeamConvergenceOnPerturbedHexAndTheCorrectionsGain) {
  const BeamSeries corrected = beam_series(MeshFamily::perturbed_hex, true);
  expect_corrected_rates(corrected, MeshFamily::perturbed_hex);
  const BeamSeries uncorrected = beam_series(MeshFamily::perturbed_hex, false);
  EXPECT_GT(uncorrected.energy.back(), corrected.energy.back())
      << "perturbed-hex: the uncorrected energy error at the finest level should exceed the "
         "corrected one";
}

// ------------------------------------------------------------------------------------------
// 4. Volumetric locking and mean dilation
// ------------------------------------------------------------------------------------------

TEST(CgElasticity, MeanDilationRemovesLocking) {
  const Rectangle domain(0.0, -0.5, kBeamL, 0.5);
  const PolygonMesh mesh =
      make_mesh(MeshFamily::perturbed_hex, domain, 0.05, /*seed=*/2024, /*r=*/0.2);
  SolveSettings s;
  s.problem = "beam";
  s.plane = PlaneModel::strain;
  std::map<std::pair<double, bool>, SolveResult> r;
  for (double nu : {0.3, 0.4999})
    for (bool md : {true, false}) {
      s.nu = nu;
      s.mean_dilation = md;
      r[{nu, md}] = run_solve(mesh, s);
    }
  std::cout << "plane strain beam, perturbed-hex r = 0.2, h = 0.05 (" << mesh.num_cells()
            << " cells):\n";
  for (const auto& [key, res] : r)
    std::cout << "  nu " << key.first << (key.second ? ", mean dilation   " : ", standard B      ")
              << ": L2 " << res.l2_error << ", energy " << res.energy_error << "\n";
  const double md_03 = r[{0.3, true}].l2_error, md_05 = r[{0.4999, true}].l2_error;
  const double std_05 = r[{0.4999, false}].l2_error;
  std::cout << "  locking factors: mean dilation nu 0.4999 / nu 0.3 = " << md_05 / md_03
            << ", standard / mean dilation at nu 0.4999 = " << std_05 / md_05 << "\n";
  EXPECT_LE(md_05, 2.0 * md_03);
  EXPECT_GT(std_05, 5.0 * md_05);
}

// ------------------------------------------------------------------------------------------
// 5. Threads and other properties
// ------------------------------------------------------------------------------------------

TEST(CgElasticity, ThreadCountDoesNotChangeTheSolution) {
  const ElementTable& table = table_of(family_named("rcp"), 3, true);
  const IsotropicElasticity material(1.0, 0.3, PlaneModel::stress);
  const ManufacturedSolution mms(material, table.mesh().domain());
  const AffineField mixed(material, AffineField::Supports::mixed);
  for (const ExactSolution* problem :
       {static_cast<const ExactSolution*>(&mms), static_cast<const ExactSolution*>(&mixed)})
    for (bool md : {false, true}) {
      const ElasticityIntegrator integrator(table, material, md);
      CgElasticity one(table, integrator, *problem, 1), two(table, integrator, *problem, 2);
      one.run();
      two.run();
      EXPECT_TRUE((one.vertex_displacement().array() == two.vertex_displacement().array()).all())
          << problem->name() << " mean dilation " << md << ": max difference "
          << (one.vertex_displacement() - two.vertex_displacement()).cwiseAbs().maxCoeff();
      EXPECT_EQ(one.factorization().rcond, two.factorization().rcond);
    }
}

// Element setup, chunked assembly, the cell mean operators, the node-graph ordering (the mesh
// is large enough for METIS: about 1e4 unknowns) and the error integration, for CG and DG, with
// and without mean dilation: the same bits for 1 and 2 threads.
TEST(CgElasticity, WholePipelineIsThreadIndependent) {
  const PolygonMesh mesh = make_mesh(MeshFamily::perturbed_hex, Rectangle(0.0, -0.5, kBeamL, 0.5),
                                     0.05, /*seed=*/3, 0.3);
  for (const char* formulation : {"cg", "dg-nitsche"})
    for (bool md : {false, true}) {
      SolveSettings s;
      s.problem = "beam";
      s.formulation = formulation;
      s.mean_dilation = md;
      s.element.threads = 1;
      const SolveResult one = run_solve(mesh, s);
      s.element.threads = 2;
      const SolveResult two = run_solve(mesh, s);
      SCOPED_TRACE(std::string(formulation) + (md ? " mean dilation" : ""));
      ASSERT_GT(one.free_dofs, 4000);
      EXPECT_TRUE((one.cell_dof_values.array() == two.cell_dof_values.array()).all());
      EXPECT_EQ(one.l2_error, two.l2_error);
      EXPECT_EQ(one.energy_error, two.energy_error);
      EXPECT_EQ(one.rcond, two.rcond);
      EXPECT_EQ(one.factor_nonzeros, two.factor_nonzeros);
      EXPECT_EQ(one.cell_l2_density, two.cell_l2_density);
      EXPECT_EQ(one.cell_energy_density, two.cell_energy_density);
      EXPECT_EQ(one.cell_mean_stress, two.cell_mean_stress);
    }
}

TEST(CgElasticity, DirichletValuesAreImposedExactly) {
  const PolygonMesh mesh = make_mesh(MeshFamily::rcp, Rectangle(0.0, -0.5, 4.0, 0.5), 0.1, 9);
  const ElementTable table(mesh, ElementOptions{});
  const IsotropicElasticity material(1.0, 0.3, PlaneModel::stress);
  const TimoshenkoBeam beam(material, 4.0, 1.0, 1.0);
  const ElasticityIntegrator integrator(table, material, false);
  CgElasticity cg(table, integrator, beam);
  cg.run();
  std::set<int> left;
  for (const MeshEdge& e : mesh.edges())
    if (e.on_boundary() && e.side == Side::left) left.insert({e.v0, e.v1});
  ASSERT_GT(left.size(), 5u);
  int on_left_geometrically = 0;
  for (int v = 0; v < mesh.num_vertices(); ++v) on_left_geometrically += mesh.vertex(v).x() == 0.0;
  EXPECT_EQ(static_cast<int>(left.size()), on_left_geometrically);
  for (int v : left)
    EXPECT_EQ(cg.vertex_displacement().col(v), beam.displacement(mesh.vertex(v))) << "vertex " << v;
  EXPECT_EQ(cg.num_dofs(), 2 * mesh.num_vertices());
  EXPECT_EQ(cg.num_free_dofs(), 2 * (mesh.num_vertices() - static_cast<int>(left.size())));
  // cell_dofs gathers the vertex values in loop order.
  for (int c = 0; c < mesh.num_cells(); c += 17) {
    const Eigen::VectorXd u = cg.cell_dofs(c);
    const auto loop = mesh.cell_vertices(c);
    ASSERT_EQ(u.size(), 2 * static_cast<Eigen::Index>(loop.size()));
    for (std::size_t k = 0; k < loop.size(); ++k)
      EXPECT_EQ(u.segment<2>(2 * k), cg.vertex_displacement().col(loop[k]));
  }
  // Stage times.
  for (const char* stage : {"setup", "assembly", "factorization", "solve"}) {
    ASSERT_TRUE(cg.seconds().count(stage)) << stage;
    EXPECT_GE(cg.seconds().at(stage), 0.0) << stage;
  }
  EXPECT_GT(cg.factorization().rcond, 0.0);
  EXPECT_LE(cg.factorization().rcond, 1.0);
  // The beam is solved reasonably at this resolution.
  const ErrorReport e = compute_errors(table, beam, [&](int c) { return cg.cell_dofs(c); });
  std::cout << "beam on rcp d = 0.1: L2 " << e.l2_error << ", energy " << e.energy_error << "\n";
  EXPECT_LT(e.l2_error, 0.02);
  EXPECT_LT(e.energy_error, 0.1);
}

TEST(CgElasticity, ManufacturedSolutionConverges) {
  // All-Dirichlet with a body force: exercises the body-force load.
  const Rectangle domain(0.0, 0.0, 2.0, 1.0);
  for (MeshFamily family : {MeshFamily::rcp, MeshFamily::perturbed_hex}) {
    std::vector<double> h, l2, energy;
    for (double size : {0.1, 0.05, 0.025}) {
      const PolygonMesh mesh = make_mesh(family, domain, size, 13, 0.3);
      SolveSettings s;
      s.problem = "mms";
      const SolveResult r = run_solve(mesh, s);
      h.push_back(mesh.h_avg());
      l2.push_back(r.l2_error);
      energy.push_back(r.energy_error);
    }
    const double rate_l2 = least_squares_slope(h, l2), rate_energy = least_squares_slope(h, energy);
    std::cout << "mms on " << family_name(family) << ": L2 " << l2[0] << " " << l2[1] << " "
              << l2[2] << " (rate " << rate_l2 << "), energy " << energy[0] << " " << energy[1]
              << " " << energy[2] << " (rate " << rate_energy << ")\n";
    EXPECT_GE(rate_l2, 1.8) << family_name(family);
    EXPECT_GE(rate_energy, 0.9) << family_name(family);
  }
}

}  // namespace
}  // namespace vorodg
