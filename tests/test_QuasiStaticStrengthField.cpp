// A strength varying from edge to edge in quasi-static fracture (CohesiveFracture::
// set_edge_strength, what a scene's material.field gives the fracture kind): the faces' law and
// criterion scale by the edge's factor, the bulk does not. Checked on the tension bar, whose
// closed form is known: a uniform factor f is the same path, point for point, as the scene's law
// and criterion with strength f x sigma_c; a varying factor keeps the dissipation at separation
// G H t (G does not vary) and the energy balance, and peaks between the weakest and the strongest
// face's closed-form peak. The factors must come before setup_system and one per mesh edge.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/element/ElasticityIntegrator.hpp"
#include "core/element/ElementTable.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/util/Errors.hpp"
#include "dg/CohesiveFracture.hpp"
#include "dg/QuasiStaticPath.hpp"
#include "fracture/TensionBar.hpp"

namespace vorodg {
namespace {

constexpr double kE = 30e9, kNu = 0.2, kStrength = 3.33e6, kEnergy = 124.0, kThickness = 0.05;
constexpr double kLength = 0.2, kHeight = 0.1;

struct StrengthRun {
  std::vector<PathPoint> path;
  bool complete = false;
  std::string failure;
};

GeneratedMesh bar_mesh() {
  MeshSpec spec;
  spec.family = MeshFamily::quad;
  spec.domain = Rectangle(0.0, 0.0, kLength, kHeight);
  spec.size = 0.025;
  return generate_mesh(spec);
}

/// The bar's crack line at mid-length, where faces may crack.
FractureSetup bar_setup(const PolygonMesh& mesh) {
  const FractureGeometry geometry{fracture_problem("tension-bar"), mesh.domain(), 0.5 * kLength,
                                  0.0};
  return fracture_setup(mesh, geometry, CrackingMode::restricted, kThickness);
}

/// The bar pulled to 1.2 critical openings of the nominal law, with `strength` times the scene's
/// sigma_c in its law and criterion, and `factor` per mesh edge (empty: none).
StrengthRun run_bar(double strength, const std::vector<double>& factor) {
  const GeneratedMesh mesh = bar_mesh();
  const ElementTable table(mesh.mesh, ElementOptions{});
  const IsotropicElasticity material(kE, kNu, PlaneModel::stress);
  const ElasticityIntegrator integrator(table, material, false);
  const FractureSetup setup = bar_setup(mesh.mesh);
  const double sc = strength * kStrength;
  const CohesiveParameters law{sc, kEnergy, 1.0, "linear"};
  CohesiveFracture model(table, integrator, setup, law, {sc, 0.75, sc}, DgOptions{});
  model.set_edge_strength(factor);
  model.setup_system();
  PathOptions options;
  options.control = LoadControl::displacement;
  options.steps = 40;
  const double dc = CohesiveLaw({kStrength, kEnergy}).critical_opening();
  options.max_stroke = 1.5 * kStrength * kLength / kE + 1.2 * dc;
  QuasiStaticPath path(model, options);
  StrengthRun run;
  run.complete = path.run(
      [&](const PathPoint& p, const Eigen::VectorXd&, const auto&) { run.path.push_back(p); });
  run.failure = path.failure();
  return run;
}

double peak_load(const StrengthRun& run) {
  double peak = 0.0;
  for (const PathPoint& p : run.path) peak = std::max(peak, p.load);
  return peak;
}

TEST(CohesiveLawStrengthFactor, ScalesTheStrengthAndKeepsTheEnergy) {
  const CohesiveLaw law({kStrength, kEnergy, 0.5, "bilinear", 0.0});
  const CohesiveLaw weak = law.with_strength_factor(0.8);
  EXPECT_DOUBLE_EQ(weak.parameters().strength, 0.8 * kStrength);
  EXPECT_EQ(weak.parameters().fracture_energy, kEnergy);
  EXPECT_EQ(weak.parameters().shear_factor, 0.5);
  EXPECT_EQ(weak.parameters().shape, "bilinear");
  EXPECT_NEAR(weak.critical_opening(), law.critical_opening() / 0.8,
              1e-14 * law.critical_opening());
  EXPECT_NEAR(weak.dissipated_energy(weak.critical_opening()), kEnergy, 1e-12 * kEnergy);
  EXPECT_THROW(law.with_strength_factor(0.0), InputError);
  EXPECT_THROW(law.with_strength_factor(NAN), InputError);
}

/// A uniform factor is the scaled law and criterion: the same path to round-off.
TEST(QuasiStaticStrengthField, AUniformFactorIsTheScaledLaw) {
  const int edges = bar_mesh().mesh.num_edges();
  const StrengthRun scaled = run_bar(0.8, {});
  const StrengthRun factored = run_bar(1.0, std::vector<double>(edges, 0.8));
  ASSERT_TRUE(scaled.complete) << scaled.failure;
  ASSERT_TRUE(factored.complete) << factored.failure;
  ASSERT_EQ(scaled.path.size(), factored.path.size());
  const double peak = 0.8 * kStrength * kHeight * kThickness;
  EXPECT_NEAR(peak_load(scaled), peak, 1e-6 * peak);
  for (std::size_t i = 0; i < scaled.path.size(); ++i) {
    EXPECT_NEAR(factored.path[i].stroke, scaled.path[i].stroke, 1e-9 * scaled.path[i].stroke);
    EXPECT_NEAR(factored.path[i].load, scaled.path[i].load, 1e-9 * peak) << "point " << i;
    EXPECT_NEAR(factored.path[i].energy.dissipated, scaled.path[i].energy.dissipated,
                1e-9 * kEnergy * kHeight * kThickness);
  }
}

/// Factors from 0.8 to 1.2 along the crack line: the peak lies between the weakest and the
/// strongest face's, the bar still dissipates G H t when separated, and the balance holds.
TEST(QuasiStaticStrengthField, AVaryingStrengthDissipatesTheSameEnergy) {
  const PolygonMesh mesh = bar_mesh().mesh;
  std::vector<double> factor(mesh.num_edges());
  for (int e = 0; e < mesh.num_edges(); ++e) {  // by height: 0.8 at the bottom, 1.2 at the top
    const MeshEdge& edge = mesh.edge(e);
    const double y = 0.5 * (mesh.vertex(edge.v0).y() + mesh.vertex(edge.v1).y());
    factor[e] = 0.8 + 0.4 * y / kHeight;
  }
  const StrengthRun run = run_bar(1.0, factor);
  ASSERT_TRUE(run.complete) << run.failure;
  const double nominal = kStrength * kHeight * kThickness;
  const double peak = peak_load(run);
  EXPECT_GT(peak, 0.8 * nominal);
  EXPECT_LT(peak, 1.2 * nominal);
  const double separated = kEnergy * kHeight * kThickness;
  EXPECT_NEAR(run.path.back().energy.dissipated, separated, 1e-6 * separated);
  EXPECT_NEAR(run.path.back().load, 0.0, 1e-6 * nominal);
  for (const PathPoint& p : run.path) EXPECT_LE(p.balance_error(), 1e-3) << "step " << p.step;
}

TEST(QuasiStaticStrengthField, RefusesFactorsOfTheWrongSizeOrTooLate) {
  const GeneratedMesh mesh = bar_mesh();
  const ElementTable table(mesh.mesh, ElementOptions{});
  const IsotropicElasticity material(kE, kNu, PlaneModel::stress);
  const ElasticityIntegrator integrator(table, material, false);
  const FractureSetup setup = bar_setup(mesh.mesh);
  const CohesiveParameters law{kStrength, kEnergy, 1.0, "linear"};
  CohesiveFracture wrong(table, integrator, setup, law, {kStrength, 0.75, kStrength}, DgOptions{});
  wrong.set_edge_strength({1.0, 1.0});
  EXPECT_THROW(wrong.setup_system(), InputError);
  CohesiveFracture late(table, integrator, setup, law, {kStrength, 0.75, kStrength}, DgOptions{});
  late.setup_system();
  EXPECT_THROW(late.set_edge_strength(std::vector<double>(mesh.mesh.num_edges(), 1.0)), InputError);
}

}  // namespace
}  // namespace vorodg
