// Notched rcp meshes for cracks anywhere (MeshSpec::notch_only, scene `symmetric: "notch"`): on
// Petersson's beam domain, for several sizes and seeds, the mesh is valid; it carries the
// three-point bend's notch (edges summing to its depth), its load point and its crack mouth, so
// that fracture_setup accepts it for the contiguous and arbitrary modes; and away from the notch
// it is not symmetric: few edges on the line above the notch tip (a whole-mirrored mesh has
// them all the way up), and almost no vertex has a mirror image.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>

#include "core/mesh/MeshValidator.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/schema/SceneObject.hpp"
#include "core/util/Errors.hpp"
#include "fracture/FractureProblem.hpp"
#include "verification/static/Scene.hpp"

namespace vorodg {
namespace {

const Rectangle kBeam(0.0, 0.0, 2.0, 0.2);
constexpr double kLine = 1.0, kNotch = 0.1;

struct NotchCase {
  double d;
  std::uint64_t seed;
  double notch = kNotch;
};

void PrintTo(const NotchCase& c, std::ostream* os) {
  *os << "d=" << c.d << " seed=" << c.seed << " notch=" << c.notch;
}

MeshSpec beam_spec(const NotchCase& c, bool notch_only) {
  MeshSpec spec;
  spec.family = MeshFamily::rcp;
  spec.domain = kBeam;
  spec.size = c.d;
  spec.seed = c.seed;
  spec.symmetric = true;
  spec.notch_only = notch_only;
  if (c.notch > 0.0) spec.line_marks = {c.notch};  // as the fracture study asks for its tip
  return spec;
}

/// Interior edges on the line wholly above the notch tip.
int line_edges_above_tip(const PolygonMesh& mesh, double tip) {
  const double tol = 1e-9;
  int count = 0;
  for (int e = 0; e < mesh.num_edges(); ++e) {
    const Point &a = mesh.vertex(mesh.edge(e).v0), &b = mesh.vertex(mesh.edge(e).v1);
    if (!mesh.edge(e).on_boundary() && std::abs(a.x() - kLine) < tol &&
        std::abs(b.x() - kLine) < tol && std::min(a.y(), b.y()) >= tip - tol)
      ++count;
  }
  return count;
}

/// Of the vertices farther than `margin` from the line, the fraction whose mirror image about it
/// is a vertex too (1 for a mirrored mesh).
double mirrored_fraction(const PolygonMesh& mesh, double margin) {
  const auto key = [](double x, double y) {
    return std::pair{std::llround(x * 1e8), std::llround(y * 1e8)};
  };
  std::set<std::pair<long long, long long>> at;
  for (const Point& p : mesh.vertices()) at.insert(key(p.x(), p.y()));
  int far = 0, mirrored = 0;
  for (const Point& p : mesh.vertices()) {
    if (std::abs(p.x() - kLine) <= margin) continue;
    ++far;
    mirrored += at.count(key(2.0 * kLine - p.x(), p.y())) > 0;
  }
  return static_cast<double>(mirrored) / far;
}

class NotchMirror : public ::testing::TestWithParam<NotchCase> {};

TEST_P(NotchMirror, IsValidAndCarriesTheThreePointBend) {
  const NotchCase c = GetParam();
  const PolygonMesh mesh = generate_mesh(beam_spec(c, true)).mesh;
  const auto report = validate_mesh(mesh);
  ASSERT_TRUE(report.ok()) << report.summary();
  const FractureGeometry g{fracture_problem("three-point-bend"), kBeam, kLine, c.notch};
  for (CrackingMode mode : {CrackingMode::contiguous, CrackingMode::arbitrary}) {
    FractureSetup setup;
    ASSERT_NO_THROW(setup = fracture_setup(mesh, g, mode, 0.05));
    double notch = 0.0;
    for (int e = 0; e < mesh.num_edges(); ++e)
      if (setup.notch[e]) notch += mesh.edge_length(e);
    EXPECT_NEAR(notch, c.notch, 1e-9 * std::max(c.notch, 1.0));
    ASSERT_GE(setup.load_vertex, 0);
    EXPECT_EQ(mesh.vertex(setup.load_vertex), Point(kLine, kBeam.y1()));
    ASSERT_EQ(setup.mouth.vertices.size(), 1u);
    EXPECT_EQ(mesh.vertex(setup.mouth.vertices[0]), Point(kLine, kBeam.y0()));
  }
}

TEST_P(NotchMirror, IsRandomAwayFromTheNotch) {
  const NotchCase c = GetParam();
  const PolygonMesh notched = generate_mesh(beam_spec(c, true)).mesh;
  const PolygonMesh mirrored = generate_mesh(beam_spec(c, false)).mesh;
  const double tip = kBeam.y0() + c.notch;
  // Above the tip only the edge of the notch's last pair and the top pair's edge lie on the line.
  EXPECT_LE(line_edges_above_tip(notched, tip), 2);
  EXPECT_GE(line_edges_above_tip(mirrored, tip), static_cast<int>(0.5 * (kBeam.y1() - tip) / c.d));
  EXPECT_LT(mirrored_fraction(notched, 3.0 * c.d), 0.02);
  EXPECT_EQ(mirrored_fraction(mirrored, 3.0 * c.d), 1.0);
}

INSTANTIATE_TEST_SUITE_P(
    Beams, NotchMirror,
    ::testing::Values(NotchCase{0.02, 1}, NotchCase{0.02, 2}, NotchCase{0.02, 7},
                      NotchCase{0.02, 2008}, NotchCase{0.01, 1}, NotchCase{0.01, 3},
                      NotchCase{0.01, 2008},
                      // depths that are not a whole number of d, and no notch at all
                      NotchCase{0.03, 5}, NotchCase{0.015, 11}, NotchCase{0.02, 4, 0.0},
                      NotchCase{0.02, 6, 0.05}));

// Many seeds, coarse to fine, with depths of any fraction of d: every mesh is valid and carries
// the notch (the generator throws if a mark or a notch edge is missing).
TEST(NotchMirrorSeeds, EveryRealizationCarriesTheNotch) {
  const int seeds = 20;  // 300 each also passed when this was written
  for (double d : {0.04, 0.03, 0.025, 0.015, 0.0075})
    for (int seed = 1; seed <= seeds; ++seed) {
      const NotchCase c{d, static_cast<std::uint64_t>(seed)};
      PolygonMesh mesh;
      ASSERT_NO_THROW(mesh = generate_mesh(beam_spec(c, true)).mesh)
          << "d " << d << " seed " << seed;
      const auto report = validate_mesh(mesh);
      ASSERT_TRUE(report.ok()) << "d " << d << " seed " << seed << ": " << report.summary();
      const FractureGeometry g{fracture_problem("three-point-bend"), kBeam, kLine, c.notch};
      ASSERT_NO_THROW(fracture_setup(mesh, g, CrackingMode::arbitrary, 0.05))
          << "d " << d << " seed " << seed;
    }
}

TEST(NotchMirrorSpec, RefusesWhatItCannotBuild) {
  MeshSpec spec = beam_spec({0.02, 1}, true);
  spec.line_marks = {0.19};  // no room for the top's pair above the tip
  EXPECT_THROW(generate_mesh(spec), InputError);
  spec.line_marks = {0.05, 0.1};
  EXPECT_THROW(generate_mesh(spec), InputError);
  spec = beam_spec({0.02, 1}, true);
  spec.symmetric = false;
  EXPECT_THROW(generate_mesh(spec), InputError);
}

SceneMesh scene_mesh(const std::string& object) {
  const nlohmann::json value = nlohmann::json::parse(object);
  const std::string source = "notch.json";
  SceneObject m(value, "meshes[0]", source);
  return read_mesh(m, kBeam);
}

TEST(NotchMirrorScene, SymmetricTakesTrueFalseOrNotch) {
  EXPECT_TRUE(scene_mesh(R"({"sizes": [0.02], "symmetric": "notch"})").notch_only);
  const SceneMesh whole = scene_mesh(R"({"sizes": [0.02], "symmetric": true})");
  EXPECT_TRUE(whole.symmetric);
  EXPECT_FALSE(whole.notch_only);
  const SceneMesh notch = scene_mesh(R"({"sizes": [0.02], "symmetric": "notch"})");
  const MeshSpec spec = notch.spec(kBeam, 0, 9);
  EXPECT_TRUE(spec.symmetric && spec.notch_only);
  EXPECT_FALSE(scene_mesh(R"({"sizes": [0.02], "symmetric": false})").symmetric);
  try {
    scene_mesh(R"({"sizes": [0.02], "symmetric": "half"})");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(
        std::string(e.what()).find("'meshes[0].symmetric': expected true, false or \"notch\""),
        std::string::npos)
        << e.what();
  }
  EXPECT_THROW(scene_mesh(R"({"family": "hex", "sizes": [0.02], "symmetric": "notch"})"),
               InputError);
}

}  // namespace
}  // namespace vorodg
