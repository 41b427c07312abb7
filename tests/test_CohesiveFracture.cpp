// Cohesive fracture in the DG form, end to end on closed forms: the tension bar follows the
// closed form (elastic to sigma_c, then sigma = T(w), stroke = sigma L / E + w) at every converged
// point, under displacement control (a short bar), and crack-mouth-opening control and the
// dissipation arc-length through snap-back (a long bar), with both laws; the dissipated energy
// after separation is G H t; the energy balance holds at every point; and below the strength
// nothing differs from elasticity. The bar runs on quad meshes and on an imported .vtu
// (data/meshes/bar-symmetric-d0.02.vtu). The faces the model reports cracked, and the cells it
// marks open, are the crack line's once the bar has separated.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "core/element/ElasticityIntegrator.hpp"
#include "core/element/ElementTable.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "dg/CohesiveFracture.hpp"
#include "dg/QuasiStaticPath.hpp"
#include "fracture/TensionBar.hpp"

namespace vorodg {
namespace {

constexpr double kE = 30e9, kNu = 0.2, kStrength = 3.33e6, kEnergy = 124.0, kThickness = 0.05;

struct BarCase {
  MeshFamily family;
  double length;
  std::string shape;
  LoadControl control;
  std::string mesh_file = "";  // family file: a .vtu under data/meshes
};

/// The shipped imported meshes (data/meshes).
const std::string kMeshes =
    (std::filesystem::path(VORODG_TEST_DATA).parent_path().parent_path() / "data" / "meshes")
        .string();

struct BarRun {
  std::vector<PathPoint> path;
  std::vector<double> cmod;
  bool complete = false;
  std::string failure;
  FractureGeometry geometry;
  // What the model reports of its cracks at the start and at the last point, and which cells
  // have a vertex on the crack line.
  std::vector<CrackedFace> cracked_at_start, cracked_at_end;
  std::vector<double> states_at_start, states_at_end;
  std::vector<char> on_line;
};

BarRun run_bar(const BarCase& c, double max_cmod_fraction = 1.2, int steps = 40) {
  MeshSpec spec;
  spec.family = c.family;
  spec.domain = Rectangle(0.0, 0.0, c.length, 0.1);
  spec.size = 0.025;
  spec.seed = 3;
  if (c.family == MeshFamily::file) spec.path = kMeshes + "/" + c.mesh_file;
  const GeneratedMesh mesh = generate_mesh(spec);
  const ElementTable table(mesh.mesh, ElementOptions{});
  const IsotropicElasticity material(kE, kNu, PlaneModel::stress);
  const ElasticityIntegrator integrator(table, material, false);
  BarRun run;
  run.geometry = {fracture_problem("tension-bar"), spec.domain, 0.5 * c.length, 0.0};
  const FractureSetup setup =
      fracture_setup(mesh.mesh, run.geometry, CrackingMode::restricted, kThickness);
  const CohesiveParameters law{kStrength, kEnergy, 1.0, c.shape};
  CohesiveFracture model(table, integrator, setup, law, {kStrength, 0.75, kStrength}, DgOptions{});
  model.setup_system();
  PathOptions options;
  options.control = c.control;
  options.steps = steps;
  const double dc = CohesiveLaw(law).critical_opening();
  options.max_cmod = max_cmod_fraction * dc;
  options.max_stroke = kStrength * c.length / kE + max_cmod_fraction * dc;
  QuasiStaticPath path(model, options);
  run.cracked_at_start = model.cracked_faces(model.initial_points());
  run.states_at_start = model.cell_interface_states(model.initial_points());
  run.complete = path.run([&](const PathPoint& p, const Eigen::VectorXd&, const auto& points) {
    run.path.push_back(p);
    run.cracked_at_end = model.cracked_faces(points);
    run.states_at_end = model.cell_interface_states(points);
  });
  run.failure = path.failure();
  for (int c = 0; c < mesh.mesh.num_cells(); ++c) {
    bool touches = false;
    for (int v : mesh.mesh.cell_vertices(c))
      touches |= std::abs(mesh.mesh.vertex(v).x() - run.geometry.line_x) < 1e-12;
    run.on_line.push_back(touches);
  }
  return run;
}

class TensionBar : public ::testing::TestWithParam<BarCase> {};

TEST_P(TensionBar, FollowsTheClosedFormAtEveryPoint) {
  const BarCase c = GetParam();
  const BarRun run = run_bar(c);
  ASSERT_TRUE(run.complete) << run.failure << " after " << run.path.size() << " points";
  ASSERT_GT(run.path.size(), 10u);
  const IsotropicElasticity material(kE, kNu, PlaneModel::stress);
  const CohesiveLaw law({kStrength, kEnergy, 1.0, c.shape});
  const double peak = kStrength * 0.1 * kThickness;
  for (const PathPoint& p : run.path) {
    // The crack opening is the cmod; before the crack it is zero and the bar is elastic.
    const BarResponse cf = tension_bar_closed_form(run.geometry, material, law, kThickness, p.cmod);
    if (p.cmod <= 1e-9 * law.critical_opening()) {  // intact: the gauge reads round-off
      EXPECT_NEAR(p.load, kE * p.stroke / c.length * 0.1 * kThickness, 1e-6 * peak)
          << "step " << p.step;
    } else {
      EXPECT_NEAR(p.load, cf.load, 1e-6 * peak) << "step " << p.step;
      EXPECT_NEAR(p.stroke, cf.stroke, 1e-6 * cf.stroke) << "step " << p.step;
    }
    EXPECT_LE(p.balance_error(), 1e-3) << "step " << p.step;
  }
  const PathPoint& last = run.path.back();
  EXPECT_NEAR(last.energy.dissipated, kEnergy * 0.1 * kThickness,
              1e-6 * kEnergy * 0.1 * kThickness);
}

/// Past the critical opening the bar has separated along its crack line: every face the model
/// reports as cracked lies on the line and is open, together they span the bar's height, and
/// the cells it marks open are those beside the line. At the start nothing is cracked.
TEST(TensionBarCracks, AfterSeparationTheCrackedFacesAreTheCrackLineOpen) {
  const BarRun run = run_bar({MeshFamily::quad, 0.2, "linear", LoadControl::displacement});
  ASSERT_TRUE(run.complete) << run.failure;
  EXPECT_TRUE(run.cracked_at_start.empty());
  for (double s : run.states_at_start) EXPECT_EQ(s, 0.0);
  ASSERT_FALSE(run.cracked_at_end.empty());
  double length = 0.0;
  for (const CrackedFace& f : run.cracked_at_end) {
    EXPECT_NEAR(f.a.x(), run.geometry.line_x, 1e-12);
    EXPECT_NEAR(f.b.x(), run.geometry.line_x, 1e-12);
    EXPECT_TRUE(f.open);
    length += (f.b - f.a).norm();
  }
  EXPECT_NEAR(length, 0.1, 1e-12);
  for (std::size_t c = 0; c < run.states_at_end.size(); ++c)
    EXPECT_EQ(run.states_at_end[c], run.on_line[c] ? 2.0 : 0.0) << "cell " << c;
}

INSTANTIATE_TEST_SUITE_P(
    Bars, TensionBar,
    ::testing::Values(
        BarCase{MeshFamily::quad, 0.2, "linear", LoadControl::displacement},
        BarCase{MeshFamily::quad, 0.2, "bilinear", LoadControl::displacement},
        BarCase{MeshFamily::quad, 2.0, "linear", LoadControl::cmod},
        BarCase{MeshFamily::quad, 2.0, "bilinear", LoadControl::cmod},
        // Through the snap-back by the energy each step releases (dissipation arc-length).
        BarCase{MeshFamily::quad, 2.0, "linear", LoadControl::arc_length},
        BarCase{MeshFamily::quad, 2.0, "bilinear", LoadControl::arc_length},
        // An imported symmetric rcp mesh (d = 0.02) whose crack line x = 0.1 is made of edges.
        BarCase{MeshFamily::file, 0.2, "linear", LoadControl::displacement,
                "bar-symmetric-d0.02.vtu"},
        BarCase{MeshFamily::file, 0.2, "bilinear", LoadControl::displacement,
                "bar-symmetric-d0.02.vtu"}));

/// The bar with its crack line's faces pre-inserted, pulled past separation, its tangents
/// factored through the faces' Schur complement or whole.
struct CondensedBar {
  std::vector<PathPoint> path;
  bool complete = false, condensing = false;
};

CondensedBar pre_inserted_bar(bool condense) {
  MeshSpec spec;
  spec.family = MeshFamily::rcp;
  spec.domain = Rectangle(0.0, 0.0, 0.2, 0.1);
  spec.size = 0.02;
  spec.seed = 3;
  spec.symmetric = true;  // the crack line made of edges
  const GeneratedMesh mesh = generate_mesh(spec);
  const ElementTable table(mesh.mesh, ElementOptions{});
  const ElasticityIntegrator integrator(table, IsotropicElasticity(kE, kNu, PlaneModel::stress),
                                        false);
  const FractureGeometry geometry{fracture_problem("tension-bar"), spec.domain, 0.1, 0.0};
  const FractureSetup setup =
      fracture_setup(mesh.mesh, geometry, CrackingMode::pre_inserted, kThickness);
  // An intrinsic law, K0 = 10 E / h as the notched beam's scenes take it.
  const CohesiveParameters law{kStrength, kEnergy, 1.0, "linear", 10.0 * kE / spec.size};
  CohesiveFracture model(table, integrator, setup, law, {kStrength, 0.75, kStrength}, DgOptions{});
  model.setup_system();
  PathOptions options;
  options.control = LoadControl::displacement;
  options.steps = 30;
  options.max_stroke = kStrength * 0.2 / kE + 1.2 * CohesiveLaw(law).critical_opening();
  options.condense_faces = condense;
  QuasiStaticPath path(model, options);
  CondensedBar run;
  run.complete = path.run(
      [&](const PathPoint& p, const Eigen::VectorXd&, const auto&) { run.path.push_back(p); });
  run.condensing = path.condensing();
  return run;
}

TEST(PreInsertedFaces, TheCondensedTangentFollowsTheSamePath) {
  const CondensedBar condensed = pre_inserted_bar(true), whole = pre_inserted_bar(false);
  ASSERT_TRUE(condensed.complete);
  ASSERT_TRUE(whole.complete);
  EXPECT_TRUE(condensed.condensing);  // it never had to fall back to the whole tangent
  EXPECT_FALSE(whole.condensing);
  ASSERT_EQ(condensed.path.size(), whole.path.size());
  double peak = 0.0;
  for (const PathPoint& p : whole.path) peak = std::max(peak, p.load);
  ASSERT_GT(peak, 0.0);
  for (std::size_t k = 0; k < whole.path.size(); ++k) {
    // Both converge to Newton's tolerance (1e-10 of the force scale): the same points to far
    // below anything a figure shows.
    EXPECT_NEAR(condensed.path[k].load, whole.path[k].load, 1e-7 * peak) << k;
    EXPECT_NEAR(condensed.path[k].energy.dissipated, whole.path[k].energy.dissipated,
                1e-7 * std::max(whole.path.back().energy.dissipated, 1e-300))
        << k;
  }
  EXPECT_GT(whole.path.back().energy.dissipated, 0.0);  // the faces did soften
  // The same tangent: Newton takes the same iterations (a wrong Schur complement would still
  // converge on the residual, in many more).
  int iterations[2] = {0, 0};
  for (const PathPoint& p : condensed.path) iterations[0] += p.iterations;
  for (const PathPoint& p : whole.path) iterations[1] += p.iterations;
  EXPECT_LE(std::abs(iterations[0] - iterations[1]), 2) << iterations[0] << " " << iterations[1];
}

}  // namespace
}  // namespace vorodg
