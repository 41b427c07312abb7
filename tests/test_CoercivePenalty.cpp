// The coercive interior penalty (penalty auto): the trace constants against a brute-force
// eigenproblem, the coercivity argument checked on the assembled matrix, and own-stress SIPG
// passing the patch tests on every family, on raw Voronoi meshes and on meshes with edges down
// to 1e-3 h_avg, and matching CG on the beam.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <iostream>

#include "cg/CgElasticity.hpp"
#include "core/mesh/MeshValidator.hpp"
#include "core/problem/AffineField.hpp"
#include "core/problem/ErrorNorms.hpp"
#include "core/problem/TimoshenkoBeam.hpp"
#include "dg/DgElasticity.hpp"
#include "interfaces/TraceConstants.hpp"
#include "support/ElementTestMeshes.hpp"

namespace vorodg {
namespace {

using testing::kFamilies;
using testing::make_mesh;

const Rectangle kBox(0.0, 0.0, 2.0, 1.0);

/// `mesh` with one interior edge shortened to `ratio` h_avg by moving its second vertex along
/// it: the first interior edge (longest first) for which the result is a valid mesh whose cells
/// the element layer accepts.
PolygonMesh with_short_edge(const PolygonMesh& mesh, double ratio) {
  std::vector<int> order(mesh.num_edges());
  for (int e = 0; e < mesh.num_edges(); ++e) order[e] = e;
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return mesh.edge_length(a) > mesh.edge_length(b); });
  for (int e : order) {
    const MeshEdge& edge = mesh.edge(e);
    if (edge.on_boundary() || mesh.vertex_cells(edge.v0).size() < 3 ||
        mesh.vertex_cells(edge.v1).size() < 3)
      continue;
    std::vector<Point> vertices = mesh.vertices();
    const Eigen::Vector2d along = (vertices[edge.v1] - vertices[edge.v0]).normalized();
    vertices[edge.v1] = vertices[edge.v0] + ratio * mesh.h_avg() * along;
    PolygonMesh moved(mesh.domain(), vertices, mesh.offsets(), mesh.cell_vertex_list());
    if (!validate_mesh(moved).ok()) continue;
    try {
      ElementTable check(moved, ElementOptions{});
    } catch (const std::exception&) {
      continue;
    }
    return moved;
  }
  throw std::runtime_error("no edge could be shortened");
}

double shortest_edge(const PolygonMesh& mesh) {
  double s = INFINITY;
  for (int e = 0; e < mesh.num_edges(); ++e) s = std::min(s, mesh.edge_length(e));
  return s / mesh.h_avg();
}

struct NamedMesh {
  std::string name;
  PolygonMesh mesh;
};

/// Small meshes for the eigenvalue checks: raw Voronoi (no regularization) on three seeds, a
/// perturbed hexagon mesh, and raw Voronoi with an edge of 1e-2 and 1e-3 h_avg.
const std::vector<NamedMesh>& small_meshes() {
  static const std::vector<NamedMesh> meshes = [] {
    std::vector<NamedMesh> out;
    for (std::uint64_t seed : {3, 4, 5}) {
      MeshSpec spec;
      spec.domain = kBox;
      spec.size = 0.25;
      spec.seed = seed;
      spec.regularization = 0.0;
      out.push_back({"raw rcp seed " + std::to_string(seed), generate_mesh(spec).mesh});
    }
    out.push_back({"perturbed-hex 0.4", make_mesh(MeshFamily::perturbed_hex, kBox, 0.25, 6, 0.4)});
    for (double ratio : {1e-2, 1e-3})
      out.push_back({"raw rcp, edge " + std::to_string(ratio) + " h_avg",
                     with_short_edge(out.front().mesh, ratio)});
    return out;
  }();
  return meshes;
}

DgOptions coercive(double kp, TractionKind kind, bool weighted) {
  DgOptions o;
  o.formulation = "dg-sipg";
  o.penalty = PenaltyScaling::coercive;
  o.kp = kp;
  o.traction = kind;
  o.weighted_average = weighted;
  return o;
}

const char* traction_label(TractionKind kind) {
  return kind == TractionKind::point ? "point" : kind == TractionKind::fan ? "fan" : "mean";
}

double smallest_eigenvalue(const Eigen::SparseMatrix<double>& A) {
  const Eigen::MatrixXd dense(A);
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dense, Eigen::EigenvaluesOnly)
      .eigenvalues()
      .minCoeff();
}

TEST(TraceConstants, MatchABruteForceEigenproblem) {
  const IsotropicElasticity material(1.0, 0.3, PlaneModel::stress);
  for (const NamedMesh& m : small_meshes()) {
    const ElementTable table(m.mesh, ElementOptions{});
    const ElasticityIntegrator integrator(table, material, false);
    const DgSpace space(m.mesh);
    const InterfaceOperators ops(space, integrator, table);
    for (TractionKind kind : {TractionKind::point, TractionKind::fan, TractionKind::mean}) {
      const TraceConstants constants(ops, integrator.all_cell_matrices(2), kind, 2);
      double worst = 0.0, largest = 0.0;
      for (int c = 0; c < m.mesh.num_cells(); ++c) {
        const std::vector<double> brute = TraceConstants::brute_force(ops, integrator, kind, c);
        for (std::size_t k = 0; k < brute.size(); ++k) {
          worst = std::max(worst, std::abs(constants.constant(c, k) - brute[k]) / brute[k]);
          largest = std::max(largest, brute[k] * m.mesh.h_avg());
        }
      }
      std::cout << m.name << ", " << traction_label(kind) << " stress: largest C h_avg " << largest
                << ", worst relative difference " << worst << "\n";
      EXPECT_LT(worst, 1e-8) << m.name;
    }
  }
}

TEST(CoercivePenalty, TheProvenBoundMakesTheSymmetricFormPositiveDefinite) {
  // docs/dg.md: with eps_F = k_p eta_F the form is bounded below by (k_p - 1/2) times the
  // penalty and 1/2 times the energy, so every k_p > 1/2 must give a positive definite matrix.
  // A penalty far below the bound must not (else the check could not fail).
  const IsotropicElasticity material(1.0, 0.3, PlaneModel::stress);
  for (const NamedMesh& m : small_meshes()) {
    const ElementTable table(m.mesh, ElementOptions{});
    const ElasticityIntegrator integrator(table, material, false);
    const AffineField field(material, AffineField::Supports::dirichlet);
    for (TractionKind kind : {TractionKind::point, TractionKind::fan, TractionKind::mean})
      for (bool weighted : {false, true}) {
        double at_bound = 0.0;
        for (double kp : {0.51, 1.0, 1e-3}) {
          DgElasticity dg(table, integrator, field, coercive(kp, kind, weighted));
          dg.setup_system();
          dg.assemble_system();
          const double lowest = smallest_eigenvalue(dg.system_matrix());
          if (kp == 1.0) at_bound = lowest;
          if (kp > 0.5)
            EXPECT_GT(lowest, 0.0) << m.name << " k_p " << kp << " weighted " << weighted;
          else
            EXPECT_LT(lowest, 0.0) << m.name << ": far below the bound, still definite";
        }
        std::cout << m.name << ", " << traction_label(kind) << (weighted ? ", weighted" : ", plain")
                  << ": smallest eigenvalue at k_p = 1: " << at_bound << "\n";
      }
  }
}

struct PatchMesh {
  std::string name;
  PolygonMesh mesh;
};

std::vector<PatchMesh> patch_meshes() {
  std::vector<PatchMesh> out;
  for (const testing::Family& f : kFamilies) out.push_back({f.name, testing::mesh_of(f)});
  MeshSpec raw;
  raw.domain = kBox;
  raw.size = 0.1;
  raw.seed = 17;
  raw.regularization = 0.0;
  out.push_back({"raw rcp", generate_mesh(raw).mesh});
  for (double ratio : {1e-2, 1e-3})
    out.push_back({"raw rcp, edge " + std::to_string(ratio) + " h_avg",
                   with_short_edge(out.back().mesh, ratio)});
  return out;
}

TEST(CoercivePenalty, OwnStressSipgPassesThePatchTestsEverywhere) {
  const IsotropicElasticity material(1.0, 0.3, PlaneModel::stress);
  for (const PatchMesh& m : patch_meshes()) {
    const ElementTable table(m.mesh, ElementOptions{});
    const ElasticityIntegrator integrator(table, material, false);
    for (auto supports : {AffineField::Supports::dirichlet, AffineField::Supports::mixed}) {
      const AffineField field(material, supports);
      DgOptions o;  // the defaults: own-stress symmetric SIPG with the proven penalty
      o.formulation = "dg-sipg";
      DgElasticity dg(table, integrator, field, o);
      ASSERT_NO_THROW(dg.run()) << m.name;
      const ErrorReport e = compute_errors(table, field, [&](int c) { return dg.cell_dofs(c); });
      const std::vector<double> eps = dg.penalty().relative_to_h_avg();
      const auto worst = std::max_element(eps.begin(), eps.end()) - eps.begin();
      std::cout << m.name << " (shortest edge " << shortest_edge(m.mesh) << " h_avg) "
                << field.name() << ": L2 " << e.l2_error << ", energy " << e.energy_error
                << ", rcond " << dg.factorization().rcond << ", largest eps h_avg/E " << eps[worst]
                << " on an edge of " << dg.space().interfaces()[worst].length / m.mesh.h_avg()
                << " h_avg\n";
      EXPECT_LT(e.l2_error, 1e-10) << m.name << " " << field.name();
      EXPECT_LT(e.energy_error, 1e-10) << m.name << " " << field.name();
    }
  }
}

TEST(CoercivePenalty, BeamErrorIsCgsWithinOnePercent) {
  // Own-stress SIPG is a different discretization with more DOFs: its error may be lower than
  // CG's; it must not be higher by more than 1% (L2 and energy).
  const IsotropicElasticity material(1.0, 0.3, PlaneModel::stress);
  const TimoshenkoBeam beam(material, 4.0, 1.0, 1.0);
  const PolygonMesh mesh = make_mesh(MeshFamily::rcp, Rectangle(0.0, -0.5, 4.0, 0.5), 0.1, 2008);
  const ElementTable table(mesh, ElementOptions{});
  const ElasticityIntegrator integrator(table, material, false);
  CgElasticity cg(table, integrator, beam);
  cg.run();
  DgOptions o;
  o.formulation = "dg-sipg";
  DgElasticity dg(table, integrator, beam, o);
  dg.run();
  const ErrorReport ec = compute_errors(table, beam, [&](int c) { return cg.cell_dofs(c); });
  const ErrorReport ed = compute_errors(table, beam, [&](int c) { return dg.cell_dofs(c); });
  std::cout << "beam, " << mesh.num_cells() << " cells: L2 CG " << ec.l2_error << ", SIPG "
            << ed.l2_error << "; energy CG " << ec.energy_error << ", SIPG " << ed.energy_error
            << "\n";
  EXPECT_LT(ed.l2_error, 1.01 * ec.l2_error);
  EXPECT_LT(ed.energy_error, 1.01 * ec.energy_error);
  EXPECT_GT(ed.l2_error, 0.9 * ec.l2_error);  // the same discretization error, not a fluke
}

}  // namespace
}  // namespace vorodg
