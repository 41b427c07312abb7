// `vorodg mesh` end to end: runs the built program. Generation writes a valid .vtu and a stats
// JSON with the documented keys; `--check` accepts generated and good files and rejects bad ones
// with exit code 2; bad options give exit code 2, exactly one line on stderr and no output file;
// the same seed gives byte-identical files.
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/io/AtomicFile.hpp"
#include "core/io/VtuMesh.hpp"
#include "core/mesh/MeshValidator.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "support/RunVorodg.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kExe = VORODG_EXE;
const fs::path kData = VORODG_TEST_DATA;

// "stem<i>ext" (built with a stream: GCC 12 warns falsely on "literal" + std::string).
std::string numbered(const char* stem, std::size_t i, const char* ext) {
  std::ostringstream os;
  os << stem << i << ext;
  return os.str();
}

class MeshCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("vorodg_test_MeshCommand_" + std::string(info->name()) +
                                        "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  RunResult run(const std::vector<std::string>& args) const {
    return run_program(kExe, args, dir_);
  }

  static std::string describe(const std::vector<std::string>& args, const RunResult& r) {
    std::string s = "vorodg";
    for (const auto& a : args) s += " " + a;
    return s + "\n  exit " + std::to_string(r.exit_code) + " signal " + std::to_string(r.signal) +
           "\n  stderr: " + r.err + "\n  stdout: " + r.out.substr(0, 500);
  }

  // Bad input: exit code 2, one line on stderr, neither output file created.
  void expect_rejected(std::vector<std::string> args) {
    const fs::path out = dir_ / "rejected.vtu";
    const fs::path stats = dir_ / "rejected.json";
    args.insert(args.end(), {"-o", out.string(), "--stats", stats.string()});
    const RunResult r = run(args);
    EXPECT_EQ(r.exit_code, 2) << describe(args, r);
    EXPECT_EQ(r.signal, 0) << describe(args, r);
    EXPECT_EQ(r.err_lines(), 1) << describe(args, r);
    EXPECT_FALSE(fs::exists(out)) << describe(args, r);
    EXPECT_FALSE(fs::exists(stats)) << describe(args, r);
    // No stray temporary files either.
    for (const auto& e : fs::directory_iterator(dir_))
      ADD_FAILURE() << "left behind: " << e.path() << "\n" << describe(args, r);
  }

  fs::path dir_;
};

void expect_common_stats(const json& s, const PolygonMesh& m) {
  for (const char* key :
       {"cells", "vertices", "edges", "boundary_edges", "h_avg", "min_edge", "min_edge_over_h_avg",
        "min_interior_angle_deg", "area_error", "side_counts_after"})
    EXPECT_TRUE(s.contains(key)) << "missing key " << key << " in " << s.dump();
  EXPECT_EQ(s.value("cells", -1), m.num_cells());
  EXPECT_EQ(s.value("vertices", -1), m.num_vertices());
  EXPECT_EQ(s.value("edges", -1), m.num_edges());
  int boundary = 0;
  double min_edge = std::numeric_limits<double>::infinity();
  for (int e = 0; e < m.num_edges(); ++e) {
    boundary += m.edge(e).on_boundary();
    min_edge = std::min(min_edge, m.edge_length(e));
  }
  EXPECT_EQ(s.value("boundary_edges", -1), boundary);
  EXPECT_NEAR(s.value("h_avg", 0.0), std::sqrt(m.domain().area() / m.num_cells()),
              1e-12 * m.h_avg());
  EXPECT_NEAR(s.value("min_edge", 0.0), min_edge, 1e-12 * min_edge);
  EXPECT_NEAR(s.value("min_edge_over_h_avg", 0.0), min_edge / m.h_avg(), 1e-12);
  EXPECT_GT(s.value("min_interior_angle_deg", 0.0), 0.0);
  EXPECT_LT(s.value("min_interior_angle_deg", 0.0), 180.0);
  EXPECT_LT(s.value("area_error", 1.0), 1e-12);
  ASSERT_TRUE(s["side_counts_after"].is_object());
  int total = 0;
  for (const auto& [k, n] : s["side_counts_after"].items()) {
    EXPECT_GE(std::stoi(k), 3) << k;
    total += n.get<int>();
  }
  EXPECT_EQ(total, m.num_cells());
}

TEST_F(MeshCommand, RcpGenerationWritesValidVtuAndStats) {
  const fs::path vtu = dir_ / "rcp.vtu", stats = dir_ / "rcp.json";
  const std::vector<std::string> args{
      "mesh",   "--family", "rcp", "--domain",   "0,0,2,1", "--d",         "0.04",
      "--seed", "3",        "-o",  vtu.string(), "--stats", stats.string()};
  const RunResult r = run(args);
  ASSERT_EQ(r.exit_code, 0) << describe(args, r);
  ASSERT_TRUE(fs::exists(vtu));
  ASSERT_TRUE(fs::exists(stats));
  const Rectangle dom(0, 0, 2, 1);
  const PolygonMesh m = read_vtu(vtu, &dom);
  const auto report = validate_mesh(m);
  EXPECT_TRUE(report.ok()) << report.summary();

  const json s = json::parse(read_file(stats));
  expect_common_stats(s, m);
  for (const char* key :
       {"side_counts_before", "covered_fraction", "covered_fraction_interior", "seeds", "seconds"})
    EXPECT_TRUE(s.contains(key)) << "missing rcp key " << key << " in " << s.dump();
  EXPECT_GE(s.value("seeds", 0), m.num_cells());
  EXPECT_GT(s.value("covered_fraction", 0.0), 0.45);
  EXPECT_LT(s.value("covered_fraction", 1.0), 0.65);
  EXPECT_GT(s.value("covered_fraction_interior", 0.0), 0.45);
  EXPECT_LT(s.value("covered_fraction_interior", 1.0), 0.65);
  ASSERT_TRUE(s["side_counts_before"].is_object());
  int before = 0;
  for (const auto& [k, n] : s["side_counts_before"].items()) before += n.get<int>();
  EXPECT_EQ(before, s.value("seeds", -1));
  ASSERT_TRUE(s["seconds"].is_object());
  EXPECT_FALSE(s["seconds"].empty());
  for (const auto& [stage, t] : s["seconds"].items()) {
    EXPECT_TRUE(t.is_number()) << stage;
    EXPECT_GE(t.get<double>(), 0.0) << stage;
  }
  // After regularization: 4 to 8 sides.
  for (const auto& [k, n] : s["side_counts_after"].items()) {
    EXPECT_GE(std::stoi(k), 4);
    EXPECT_LE(std::stoi(k), 8);
  }
}

TEST_F(MeshCommand, EveryStructuredFamilyGenerates) {
  const std::vector<std::vector<std::string>> cases{
      {"--family", "hex", "--h", "0.1"},
      {"--family", "perturbed-hex", "--h", "0.1", "--r", "0.3", "--seed", "4"},
      {"--family", "perturbed-hex", "--h", "0.1"},
      {"--family", "quad", "--h", "0.1"},
      {"--family", "tri", "--d", "0.1", "--seed", "2"},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const fs::path vtu = dir_ / numbered("m", i, ".vtu");
    const fs::path stats = dir_ / numbered("m", i, ".json");
    std::vector<std::string> args{"mesh"};
    args.insert(args.end(), cases[i].begin(), cases[i].end());
    args.insert(args.end(), {"-o", vtu.string(), "--stats", stats.string()});
    const RunResult r = run(args);
    ASSERT_EQ(r.exit_code, 0) << describe(args, r);
    const Rectangle dom(0, 0, 4, 1);  // the default domain
    const PolygonMesh m = read_vtu(vtu, &dom);
    const auto report = validate_mesh(m);
    EXPECT_TRUE(report.ok()) << describe(args, r) << report.summary();
    const json s = json::parse(read_file(stats));
    expect_common_stats(s, m);
    const RunResult check = run({"mesh", "--check", vtu.string()});
    EXPECT_EQ(check.exit_code, 0) << describe({"mesh", "--check", vtu.string()}, check);
  }
}

TEST_F(MeshCommand, CheckAcceptsGeneratedAndGoodFiles) {
  const fs::path vtu = dir_ / "rcp.vtu";
  const RunResult gen = run({"mesh", "--family", "rcp", "--d", "0.05", "-o", vtu.string()});
  ASSERT_EQ(gen.exit_code, 0) << gen.err;
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"mesh", "--check", vtu.string()},
        std::vector<std::string>{"mesh", "--check", vtu.string(), "--domain", "0,0,4,1"},
        std::vector<std::string>{"mesh", "--check", (kData / "good" / "quads_2x2.vtu").string()},
        std::vector<std::string>{"mesh", "--check",
                                 (kData / "good" / "mixed_cell_types.vtu").string()}}) {
    const RunResult r = run(args);
    EXPECT_EQ(r.exit_code, 0) << describe(args, r);
  }
}

TEST_F(MeshCommand, CheckRejectsMalformedFilesWithOneLine) {
  int files = 0;
  for (const auto& entry : fs::directory_iterator(kData / "bad")) {
    if (entry.path().extension() != ".vtu") continue;
    ++files;
    const std::vector<std::string> args{"mesh", "--check", entry.path().string()};
    const RunResult r = run(args);
    EXPECT_EQ(r.exit_code, 2) << describe(args, r);
    EXPECT_EQ(r.signal, 0) << describe(args, r);
    EXPECT_EQ(r.err_lines(), 1) << describe(args, r);
  }
  EXPECT_GE(files, 10);
  const std::vector<std::string> missing{"mesh", "--check", (dir_ / "missing.vtu").string()};
  const RunResult r = run(missing);
  EXPECT_EQ(r.exit_code, 2) << describe(missing, r);
  EXPECT_EQ(r.err_lines(), 1) << describe(missing, r);
}

TEST_F(MeshCommand, CheckReportsEachDefectOfAnInvalidMeshOnItsOwnLine) {
  {
    const std::vector<std::string> args{"mesh", "--check",
                                        (kData / "invalid" / "unreferenced_vertex.vtu").string()};
    const RunResult r = run(args);
    EXPECT_EQ(r.exit_code, 2) << describe(args, r);
    EXPECT_EQ(r.err_lines(), 1) << describe(args, r);
    EXPECT_NE(r.err.find('9'), std::string::npos) << "should name vertex 9: " << r.err;
  }
  for (const char* name : {"clockwise_cell.vtu", "hole.vtu"}) {
    const std::vector<std::string> args{"mesh", "--check", (kData / "invalid" / name).string()};
    const RunResult r = run(args);
    EXPECT_EQ(r.exit_code, 2) << describe(args, r);
    EXPECT_EQ(r.signal, 0) << describe(args, r);
    EXPECT_GE(r.err_lines(), 1) << describe(args, r);
  }
  // A valid mesh checked against a domain it does not fill is invalid.
  const std::vector<std::string> args{
      "mesh", "--check", (kData / "good" / "quads_2x2.vtu").string(), "--domain", "0,0,3,3"};
  const RunResult r = run(args);
  EXPECT_EQ(r.exit_code, 2) << describe(args, r);
}

TEST_F(MeshCommand, BadOptionsExitWithCodeTwoOneLineAndNoOutput) {
  const std::vector<std::vector<std::string>> cases{
      {"mesh", "--family", "rcp", "--domain", "1,0,0,1", "--d", "0.1"},
      {"mesh", "--family", "rcp", "--domain", "a,b", "--d", "0.1"},
      {"mesh", "--family", "rcp", "--domain", "0,0,1", "--d", "0.1"},
      {"mesh", "--family", "rcp", "--d", "0"},
      {"mesh", "--family", "rcp", "--d", "-0.1"},
      {"mesh", "--family", "rcp", "--d", "10"},
      {"mesh", "--family", "rcp", "--d", "abc"},
      {"mesh", "--family", "rcp", "--d", "nan"},
      {"mesh", "--family", "tri", "--d", "0"},
      {"mesh", "--family", "voronoi", "--d", "0.1"},
      {"mesh", "--family", "hex", "--h", "0"},
      {"mesh", "--family", "quad", "--h", "-1"},
      {"mesh", "--family", "perturbed-hex", "--h", "0.1", "--r", "0.7"},
      {"mesh", "--family", "perturbed-hex", "--h", "0.1", "--r", "-0.1"},
      {"mesh", "--family", "rcp", "--d", "0.1", "--regularize", "-1"},
      {"mesh", "--family", "rcp", "--d", "0.1", "--frobnicate"},
  };
  for (const auto& args : cases) {
    SCOPED_TRACE(describe(args, {}));
    expect_rejected(args);
  }
}

TEST_F(MeshCommand, UnwritableOutputIsAnInputError) {
  const std::vector<std::string> args{"mesh",
                                      "--family",
                                      "quad",
                                      "--h",
                                      "0.5",
                                      "-o",
                                      (dir_ / "no" / "such" / "folder.vtu").string()};
  const RunResult r = run(args);
  EXPECT_EQ(r.exit_code, 2) << describe(args, r);
  EXPECT_EQ(r.err_lines(), 1) << describe(args, r);
}

TEST_F(MeshCommand, SameSeedGivesByteIdenticalFiles) {
  std::vector<std::string> contents;
  for (const char* seed : {"11", "11", "12"}) {
    const fs::path vtu = dir_ / numbered("s", contents.size(), ".vtu");
    const std::vector<std::string> args{"mesh",   "--family", "rcp", "--d",       "0.04",
                                        "--seed", seed,       "-o",  vtu.string()};
    const RunResult r = run(args);
    ASSERT_EQ(r.exit_code, 0) << describe(args, r);
    contents.push_back(read_file(vtu));
  }
  EXPECT_FALSE(contents[0].empty());
  EXPECT_TRUE(contents[0] == contents[1]) << "same seed, different files";
  EXPECT_FALSE(contents[0] == contents[2]) << "different seeds, same file";
  // The perturbed-hex family too.
  std::vector<std::string> ph;
  for (int k = 0; k < 2; ++k) {
    const fs::path vtu = dir_ / numbered("ph", k, ".vtu");
    const RunResult r =
        run({"mesh", "--family", "perturbed-hex", "--h", "0.1", "--seed", "5", "-o", vtu.string()});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    ph.push_back(read_file(vtu));
  }
  EXPECT_TRUE(ph[0] == ph[1]);
}

TEST_F(MeshCommand, GeneratedFileMatchesTheLibrary) {
  // The program writes the mesh generate_mesh gives for the same spec (no hidden differences in
  // defaults); it may add cell fields of its own.
  const fs::path vtu = dir_ / "q.vtu";
  const RunResult r = run({"mesh", "--family", "rcp", "--domain", "0,0,2,1", "--d", "0.05",
                           "--seed", "8", "-o", vtu.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Rectangle dom(0, 0, 2, 1);
  const PolygonMesh m = read_vtu(vtu, &dom);
  MeshSpec spec;
  spec.family = MeshFamily::rcp;
  spec.domain = dom;
  spec.size = 0.05;
  spec.seed = 8;  // --regularize defaults to 0.1, as MeshSpec does
  const PolygonMesh lib = generate_mesh(spec).mesh;
  ASSERT_EQ(m.num_vertices(), lib.num_vertices());
  EXPECT_TRUE(m.vertices() == lib.vertices());
  EXPECT_EQ(m.offsets(), lib.offsets());
  EXPECT_EQ(m.cell_vertex_list(), lib.cell_vertex_list());
}

}  // namespace
}  // namespace vorodg
