// The `file` mesh family in scenes: one .vtu per level, named relative to the scene's folder.
// A scene with it reads (one level per file, the path resolved, the mesh's h_avg as the level's
// size), every study kind that builds meshes through SceneMesh::spec gets the file's mesh (a
// convergence study end to end, a fracture run on the shipped bar mesh), and the bad cases are
// refused with one line naming the key. Also: the shipped data/meshes/bar-symmetric-d0.02.vtu is
// the mesh its spec generates (DISABLED_WriteShippedBarMesh rewrites it).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "core/io/AtomicFile.hpp"
#include "core/io/VtuMesh.hpp"
#include "core/mesh/MeshValidator.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "core/meshgen/StructuredMeshes.hpp"
#include "core/util/Errors.hpp"
#include "support/RunVorodg.hpp"
#include "verification/kinds/fracture/FractureRun.hpp"
#include "verification/static/Scene.hpp"

namespace vorodg {
namespace {

namespace fs = std::filesystem;

const fs::path kData = VORODG_TEST_DATA;
const fs::path kRepo = kData.parent_path().parent_path();
const fs::path kBarMesh = kRepo / "data" / "meshes" / "bar-symmetric-d0.02.vtu";

/// The spec the shipped bar mesh was generated from.
MeshSpec bar_spec() {
  MeshSpec spec;
  spec.family = MeshFamily::rcp;
  spec.domain = Rectangle(0.0, 0.0, 0.2, 0.1);
  spec.size = 0.02;
  spec.seed = 2008;
  spec.symmetric = true;
  return spec;
}

/// A fresh folder holding meshes/coarse.vtu (tests/data/good/quads_2x2.vtu: 2 x 2 squares on
/// [0, 2]^2, no domain in the file) and meshes/fine.vtu (4 x 4 squares).
class SceneFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("vorodg_test_SceneFileFamily_" + std::string(info->name()) +
                                        "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "meshes");
    fs::copy_file(kData / "good" / "quads_2x2.vtu", dir_ / "meshes" / "coarse.vtu");
    write_vtu(dir_ / "meshes" / "fine.vtu", quad_mesh(Rectangle(0, 0, 2, 2), 0.5));
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// Writes a convergence scene on [0, 2]^2 with this "meshes" entry and reads it.
  Scene scene(const std::string& mesh) const {
    const fs::path file = dir_ / "scene.json";
    write_file_atomically(file, R"({"problems": ["patch"], "domain": [0, 0, 2, 2], "meshes": [)" +
                                    mesh + R"(], "formulations": [{"name": "cg"}]})");
    return read_scene(file);
  }
  /// The message a bad "meshes" entry is refused with.
  std::string refusal(const std::string& mesh) const {
    try {
      scene(mesh);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(accepted)";
  }

  fs::path dir_;
};

TEST_F(SceneFolder, ReadsOneLevelPerFile) {
  const Scene s = scene(R"({"family": "file", "files": ["meshes/coarse.vtu", "meshes/fine.vtu"],
                "label": "imported"})");
  ASSERT_EQ(s.meshes.size(), 1u);
  const SceneMesh& m = s.meshes[0];
  EXPECT_EQ(m.family, MeshFamily::file);
  EXPECT_EQ(m.label, "imported");
  EXPECT_EQ(m.realizations, 1);
  ASSERT_EQ(m.files.size(), 2u);
  EXPECT_TRUE(fs::equivalent(m.files[0], dir_ / "meshes" / "coarse.vtu"));
  EXPECT_TRUE(fs::equivalent(m.files[1], dir_ / "meshes" / "fine.vtu"));
  ASSERT_EQ(m.sizes.size(), 2u);  // the levels, as every study counts them
  EXPECT_DOUBLE_EQ(m.sizes[0], 1.0);
  EXPECT_DOUBLE_EQ(m.sizes[1], 0.5);
  for (int level = 0; level < 2; ++level) {
    const MeshSpec spec = m.spec(s.domain, level, 7);
    EXPECT_EQ(spec.family, MeshFamily::file);
    EXPECT_EQ(fs::path(spec.path), m.files[level]);
    const PolygonMesh mesh = generate_mesh(spec).mesh;
    EXPECT_EQ(mesh.num_cells(), level == 0 ? 4 : 16);
    EXPECT_TRUE(validate_mesh(mesh).ok());
  }
}

TEST_F(SceneFolder, RefusesBadFileFamiliesNamingTheKey) {
  const auto expect_refused = [&](const std::string& mesh, const std::string& mention) {
    const std::string message = refusal(mesh);
    EXPECT_NE(message.find(mention), std::string::npos) << mesh << "\n  -> " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  };
  expect_refused(R"({"family": "file", "files": ["meshes/coarse.vtu"], "sizes": [1]})",
                 "key 'meshes[0].sizes': not allowed with family file");
  expect_refused(R"({"family": "file"})", "key 'meshes[0].files': missing");
  expect_refused(R"({"family": "file", "files": ["meshes/coarse.vtu", "meshes/none.vtu"]})",
                 "key 'meshes[0].files': cannot read 'meshes/none.vtu'");
  expect_refused(R"({"family": "file", "files": ["meshes/coarse.vtu"], "realizations": 3})",
                 "key 'meshes[0].realizations': a file family has one mesh per level");
  expect_refused(R"({"family": "file", "files": ["meshes/fine.vtu", "meshes/coarse.vtu"]})",
                 "key 'meshes[0].files': levels must go from coarse to fine");
  expect_refused(R"({"family": "file", "files": ["meshes/coarse.vtu", "meshes/coarse.vtu"]})",
                 "coarse to fine");
  expect_refused(R"({"family": "file", "files": ["/dev/zero"]})",
                 "key 'meshes[0].files': cannot read '/dev/zero': not a regular file");
  expect_refused(R"({"family": "file", "files": ["meshes"]})",
                 "key 'meshes[0].files': cannot read 'meshes'");
  expect_refused(R"({"family": "file", "files": []})", "meshes[0].files");
  expect_refused(R"({"family": "file", "files": [3]})", "meshes[0].files");
  expect_refused(R"({"family": "quad", "sizes": [1], "files": ["meshes/coarse.vtu"]})",
                 "key 'meshes[0].files': only with family file");
  // Not text, and not a mesh of the scene's domain.
  write_file_atomically(dir_ / "meshes" / "junk.vtu", "not xml");
  expect_refused(R"({"family": "file", "files": ["meshes/junk.vtu"]})",
                 "key 'meshes[0].files': cannot read 'meshes/junk.vtu'");
  write_vtu(dir_ / "meshes" / "small.vtu", quad_mesh(Rectangle(0, 0, 1, 1), 0.5));
  expect_refused(R"({"family": "file", "files": ["meshes/small.vtu"]})",
                 "'meshes/small.vtu' is not a valid mesh of the domain [0, 0, 2, 2]");
  expect_refused(R"({"family": "file", "files": ["meshes/coarse.vtu"], "symmetric": true})",
                 "meshes[0].symmetric");
  expect_refused(R"({"family": "voronoi", "sizes": [1]})",
                 "expected rcp, hex, perturbed-hex, tri, quad or file");
}

// A convergence study end to end on two files: the patch test passes on both levels.
TEST_F(SceneFolder, ConvergenceStudyRunsOnTheFiles) {
  scene(R"({"family": "file", "files": ["meshes/coarse.vtu", "meshes/fine.vtu"]})");
  const testing::RunResult r =
      testing::run_program(VORODG_EXE,
                           {"run", (dir_ / "scene.json").string(), "-o", (dir_ / "out").string(),
                            "--quiet", "--no-plots"},
                           dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  const std::string results = testing::slurp(dir_ / "out" / "results.jsonl");
  EXPECT_NE(results.find("file-L0-R0/patch"), std::string::npos) << results;
  EXPECT_NE(results.find("file-L1-R0/patch"), std::string::npos) << results;
  EXPECT_EQ(results.find("file-L2-R0/"), std::string::npos);
}

// The fracture kind reads its meshes through SceneMesh::spec too: the tension bar on the shipped
// imported mesh follows the closed form.
TEST_F(SceneFolder, FractureRunReadsTheFile) {
  fs::copy_file(kBarMesh, dir_ / "meshes" / "bar.vtu");
  const fs::path file = dir_ / "bar.json";
  write_file_atomically(file, R"({"study": "fracture", "problem": "tension-bar",
    "domain": [0, 0, 0.2, 0.1], "material": {"E": 30e9, "nu": 0.2, "thickness": 0.05},
    "cohesive": {"strength": 3.33e6, "fracture_energy": 124}, "cracking": {"mode": "restricted"},
    "loading": {"control": "displacement", "max_displacement": 1.2e-4, "steps": 30},
    "outputs": {"vtu_every": 0},
    "meshes": [{"family": "file", "files": ["meshes/bar.vtu"], "label": "imported"}]})");
  const FractureScene scene = read_fracture_scene(file);
  ASSERT_EQ(scene.meshes.size(), 1u);
  ASSERT_EQ(scene.meshes[0].sizes.size(), 1u);
  const EnsembleRunId run{0, 0, 0, "imported", 1};
  ASSERT_NO_THROW(check_fracture_meshes(scene, {run}));
  const FractureRecord r = run_fracture(scene, run, dir_ / "out");
  EXPECT_TRUE(r.complete) << r.failure;
  EXPECT_EQ(r.cells, read_vtu(kBarMesh).num_cells());
  EXPECT_LE(r.closed_form_error, 1e-6);
  EXPECT_NEAR(r.dissipated_energy, 124 * 0.1 * 0.05, 1e-6 * 124 * 0.1 * 0.05);
}

TEST(ShippedMeshes, BarSymmetricIsTheMeshOfItsSpec) {
  const PolygonMesh shipped = read_vtu(kBarMesh);
  const PolygonMesh generated = generate_mesh(bar_spec()).mesh;
  ASSERT_TRUE(validate_mesh(shipped).ok()) << validate_mesh(shipped).summary();
  EXPECT_EQ(shipped.domain().x1(), 0.2);  // the domain is stored in the file
  ASSERT_EQ(shipped.num_vertices(), generated.num_vertices());
  EXPECT_EQ(shipped.cell_vertex_list(), generated.cell_vertex_list());
  for (int v = 0; v < shipped.num_vertices(); ++v)
    EXPECT_LE((shipped.vertex(v) - generated.vertex(v)).norm(), 1e-12) << "vertex " << v;
  double line = 0.0;  // the crack line x = 0.1 is made of edges from bottom to top
  for (int e = 0; e < shipped.num_edges(); ++e) {
    const MeshEdge& edge = shipped.edge(e);
    if (!edge.on_boundary() && shipped.vertex(edge.v0).x() == 0.1 &&
        shipped.vertex(edge.v1).x() == 0.1)
      line += shipped.edge_length(e);
  }
  EXPECT_NEAR(line, 0.1, 1e-12);
}

// Run with --gtest_also_run_disabled_tests to rewrite the shipped mesh from its spec.
TEST(ShippedMeshes, DISABLED_WriteShippedBarMesh) {
  fs::create_directories(kBarMesh.parent_path());
  write_vtu(kBarMesh, generate_mesh(bar_spec()).mesh, {}, VtuEncoding::ascii);
}

}  // namespace
}  // namespace vorodg
