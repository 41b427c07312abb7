// `vorodg solve --formulation dg-*` end to end: a dg-nitsche beam run writes metrics with
// every DG key (finite) and a .vtu with the cells drawn apart (points = the cells' vertex copies)
// and "max_interface_gap"; every formulation runs; bad DG options exit 2 with one line on stderr
// and write no files. (Split from test_DgElasticity.cpp, which tests the library.)
#include <unistd.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/io/AtomicFile.hpp"
#include "core/io/VtuMesh.hpp"
#include "core/meshgen/MeshFamily.hpp"
#include "support/RunVorodg.hpp"

namespace vorodg {
namespace {

// ------------------------------------------------------------------------------------------
// 7. Command line
// ------------------------------------------------------------------------------------------

namespace fs = std::filesystem;
using nlohmann::json;
using testing::RunResult;

class DgCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("vorodg_test_DgCommand_" + std::string(info->name()) + "_" +
                                        std::to_string(::getpid()));
    io_ = fs::temp_directory_path() / ("vorodg_test_DgCommand_io_" + std::string(info->name()) +
                                       "_" + std::to_string(::getpid()));
    for (const auto& d : {dir_, io_}) {
      fs::remove_all(d);
      fs::create_directories(d);
    }
  }
  void TearDown() override {
    fs::remove_all(dir_);
    fs::remove_all(io_);
  }

  RunResult run(const std::vector<std::string>& args) const {
    return testing::run_program(VORODG_EXE, args, io_);
  }

  static std::string describe(const std::vector<std::string>& args, const RunResult& r) {
    std::string s = "vorodg";
    for (const auto& a : args) s += " " + a;
    return s + "\n  exit " + std::to_string(r.exit_code) + " signal " + std::to_string(r.signal) +
           "\n  stderr: " + r.err + "\n  stdout: " + r.out.substr(0, 800);
  }

  void expect_rejected(std::vector<std::string> args) {
    const fs::path out = dir_ / "rejected.vtu", metrics = dir_ / "rejected.json";
    args.insert(args.end(), {"-o", out.string(), "--metrics", metrics.string()});
    const RunResult r = run(args);
    EXPECT_EQ(r.exit_code, 2) << describe(args, r);
    EXPECT_EQ(r.signal, 0) << describe(args, r);
    EXPECT_EQ(r.err_lines(), 1) << describe(args, r);
    EXPECT_TRUE(r.err.starts_with("vorodg: error:")) << describe(args, r);
    EXPECT_FALSE(fs::exists(out)) << describe(args, r);
    EXPECT_FALSE(fs::exists(metrics)) << describe(args, r);
  }

  fs::path dir_, io_;
};

const std::vector<std::string> kBeamArgs = {"solve",  "--family", "rcp",       "--d", "0.2",
                                            "--seed", "3",        "--problem", "beam"};

TEST_F(DgCommand, NitscheBeamWritesMetricsAndExplodedResult) {
  const fs::path out = dir_ / "result.vtu", metrics = dir_ / "metrics.json";
  std::vector<std::string> args = kBeamArgs;
  // ASCII, so the text checks below can read the values.
  args.insert(args.end(),
              {"--formulation", "dg-nitsche", "--kp", "1e3", "--tol", "1e-10", "--max-iter", "500",
               "-o", out.string(), "--metrics", metrics.string(), "--ascii"});
  const RunResult r = run(args);
  ASSERT_EQ(r.exit_code, 0) << describe(args, r);
  EXPECT_TRUE(r.err.empty()) << describe(args, r);
  ASSERT_TRUE(fs::exists(out) && fs::exists(metrics)) << describe(args, r);
  json m;
  ASSERT_NO_THROW(m = json::parse(testing::slurp(metrics)));
  EXPECT_EQ(m.value("formulation", ""), "dg-nitsche");
  for (const char* key :
       {"kp", "penalty", "iterations", "last_change", "gap_norm", "relative_gap",
        "seconds_per_iteration", "l2_error", "energy_error", "h_avg", "dofs", "cells"}) {
    ASSERT_TRUE(m.contains(key)) << "missing " << key << " in " << m.dump(2);
    ASSERT_TRUE(m[key].is_number()) << key << " in " << m.dump(2);
    EXPECT_TRUE(std::isfinite(m[key].get<double>())) << key;
    EXPECT_GE(m[key].get<double>(), 0.0) << key;
  }
  ASSERT_TRUE(m.contains("stop_reason") && m["stop_reason"].is_string()) << m.dump(2);
  EXPECT_EQ(m["stop_reason"].get<std::string>(), "converged");
  EXPECT_EQ(m["kp"].get<double>(), 1e3);
  EXPECT_NEAR(m["penalty"].get<double>(), 1e3 / m["h_avg"].get<double>(),
              1e-9 * m["penalty"].get<double>());
  EXPECT_GT(m["iterations"].get<int>(), 1);
  EXPECT_LT(m["last_change"].get<double>(), 1e-10);
  EXPECT_LT(m["l2_error"].get<double>(), 0.05);

  const std::string vtu = testing::slurp(out);
  EXPECT_NE(vtu.find("Name=\"max_interface_gap\""), std::string::npos);
  EXPECT_NE(vtu.find("Name=\"displacement\""), std::string::npos);
  std::string lower = vtu;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  EXPECT_EQ(lower.find("nan"), std::string::npos);
  EXPECT_EQ(lower.find("inf"), std::string::npos);
  const VtuCells cells = parse_vtu(vtu, out.string());
  const int cell_count = static_cast<int>(cells.offsets.size()) - 1;
  EXPECT_EQ(cell_count, m["cells"].get<int>());
  // Cells drawn apart: one point per cell vertex copy.
  EXPECT_EQ(static_cast<int>(cells.points.size()), cells.offsets.back());
  EXPECT_EQ(static_cast<int>(cells.connectivity.size()), cells.offsets.back());
  EXPECT_EQ(2 * static_cast<int>(cells.points.size()), m["dofs"].get<int>());
  EXPECT_GT(static_cast<int>(cells.points.size()), m["vertices"].get<int>());
  // Compare with the mesh itself, generated the same way.
  MeshSpec spec;
  spec.family = MeshFamily::rcp;
  spec.domain = Rectangle(0.0, -0.5, 4.0, 0.5);
  spec.size = 0.2;
  spec.seed = 3;
  const PolygonMesh mesh = generate_mesh(spec).mesh;
  if (mesh.num_cells() == cell_count) {
    EXPECT_EQ(static_cast<int>(cells.points.size()),
              static_cast<int>(mesh.cell_vertex_list().size()));
  }
}

TEST_F(DgCommand, EveryFormulationRuns) {
  // dg-sipg with its defaults: fan stresses and the proven coercive penalty.
  for (const char* f : {"dg-penalty", "dg-al", "dg-sipg"}) {
    const fs::path metrics = dir_ / "m.json";
    std::vector<std::string> args = kBeamArgs;
    args.insert(args.end(), {"--formulation", f, "--metrics", metrics.string()});
    const RunResult r = run(args);
    ASSERT_EQ(r.exit_code, 0) << describe(args, r);
    const json m = json::parse(testing::slurp(metrics));
    EXPECT_EQ(m.value("formulation", ""), f);
    EXPECT_TRUE(m.contains("stop_reason")) << f;
    EXPECT_LT(m["l2_error"].get<double>(), 0.1) << f;
    fs::remove(metrics);
  }
}

TEST_F(DgCommand, RejectsBadDgOptions) {
  for (const char* kp : {"0", "-1"}) {
    std::vector<std::string> args = kBeamArgs;
    args.insert(args.end(), {"--formulation", "dg-nitsche", "--kp", kp});
    expect_rejected(args);
  }
  {
    std::vector<std::string> args = kBeamArgs;
    args.insert(args.end(), {"--formulation", "dg-foo"});
    expect_rejected(args);
  }
  {
    std::vector<std::string> args = kBeamArgs;
    args.insert(args.end(), {"--formulation", "dg-sipg", "--sipg-sign", "0"});
    expect_rejected(args);
  }
}

}  // namespace
}  // namespace vorodg
