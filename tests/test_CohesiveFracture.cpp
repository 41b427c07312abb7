// Cohesive fracture in the DG form, end to end on closed forms: the tension bar follows the
// closed form (elastic to sigma_c, then sigma = T(w), stroke = sigma L / E + w) at every converged
// point, under displacement control (a short bar), and crack-mouth-opening control and the
// dissipation arc-length through snap-back (a long bar), with both laws; the dissipated energy
// after separation is G H t; the energy balance holds at every point; and below the strength
// nothing differs from elasticity. The bar runs on quad meshes and on an imported .vtu
// (data/meshes/bar-symmetric-d0.02.vtu).
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
  run.complete = path.run(
      [&](const PathPoint& p, const Eigen::VectorXd&, const auto&) { run.path.push_back(p); });
  run.failure = path.failure();
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

}  // namespace
}  // namespace vorodg
