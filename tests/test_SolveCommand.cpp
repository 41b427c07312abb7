// `vorodg solve` end to end: runs the built program.
// - A successful run writes a metrics JSON with the documented keys (dofs, cells, h_avg,
//   l2_error, energy_error, rcond, seconds{element, assembly, factorization, solve, error (unless
//   --no-errors), mesh}, blas), all finite, consistent with the mesh; and a .vtu with displacement,
//   exact_displacement, mean_stress and von_mises and no NaN or infinity.
// - The patch tests pass through the command line (generated and imported meshes).
// - Bad input (singular problem, nu = 0.5, nu = -1, E = 0, an invalid mesh file, the beam on a
//   domain not of the form [0,L]x[-D/2,D/2], ...): exit code 2, exactly one line on stderr
//   starting with "vorodg: error:", no output or metrics file created, nothing left behind.
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/RunVorodg.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kExe = VORODG_EXE;
const fs::path kData = VORODG_TEST_DATA;

class SolveCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("vorodg_test_SolveCommand_" + std::string(info->name()) +
                                        "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    io_ = fs::temp_directory_path() / ("vorodg_test_SolveCommand_io_" + std::string(info->name()) +
                                       "_" + std::to_string(::getpid()));
    fs::remove_all(io_);
    fs::create_directories(io_);
  }
  void TearDown() override {
    fs::remove_all(dir_);
    fs::remove_all(io_);
  }

  RunResult run(const std::vector<std::string>& args) const { return run_program(kExe, args, io_); }

  static std::string describe(const std::vector<std::string>& args, const RunResult& r) {
    std::string s = "vorodg";
    for (const auto& a : args) s += " " + a;
    return s + "\n  exit " + std::to_string(r.exit_code) + " signal " + std::to_string(r.signal) +
           "\n  stderr: " + r.err + "\n  stdout: " + r.out.substr(0, 800);
  }

  // Bad input: exit code 2, one "vorodg: error:" line on stderr, neither output file created.
  void expect_rejected(std::vector<std::string> args, const std::string& mention = "") {
    const fs::path out = dir_ / "rejected.vtu";
    const fs::path metrics = dir_ / "rejected.json";
    args.insert(args.end(), {"-o", out.string(), "--metrics", metrics.string()});
    const RunResult r = run(args);
    EXPECT_EQ(r.exit_code, 2) << describe(args, r);
    EXPECT_EQ(r.signal, 0) << describe(args, r);
    EXPECT_EQ(r.err_lines(), 1) << describe(args, r);
    EXPECT_TRUE(r.err.starts_with("vorodg: error:")) << describe(args, r);
    if (!mention.empty()) {
      EXPECT_NE(r.err.find(mention), std::string::npos)
          << "expected '" << mention << "' in the message\n"
          << describe(args, r);
    }
    EXPECT_FALSE(fs::exists(out)) << describe(args, r);
    EXPECT_FALSE(fs::exists(metrics)) << describe(args, r);
    for (const auto& e : fs::directory_iterator(dir_))
      ADD_FAILURE() << "left behind: " << e.path() << "\n" << describe(args, r);
  }

  struct Success {
    json metrics;
    std::string vtu;
  };

  // `errors`: the run measures errors (no --no-errors): the metrics carry them.
  Success expect_success(std::vector<std::string> args, bool errors = true) {
    const fs::path out = dir_ / "result.vtu";
    const fs::path metrics = dir_ / "metrics.json";
    // ASCII, so the text checks below can read the values (the default binary output is read
    // back by the meshio round trips and test_VtuMesh).
    args.insert(args.end(), {"-o", out.string(), "--metrics", metrics.string(), "--ascii"});
    const RunResult r = run(args);
    Success s;
    EXPECT_EQ(r.exit_code, 0) << describe(args, r);
    EXPECT_TRUE(r.err.empty()) << describe(args, r);
    EXPECT_TRUE(fs::exists(out)) << describe(args, r);
    EXPECT_TRUE(fs::exists(metrics)) << describe(args, r);
    if (!fs::exists(out) || !fs::exists(metrics)) return s;
    try {
      s.metrics = json::parse(slurp(metrics));
    } catch (const std::exception& e) {
      ADD_FAILURE() << "metrics are not JSON: " << e.what();
    }
    s.vtu = slurp(out);
    expect_metrics(s.metrics, errors);
    expect_clean_vtu(s.vtu);
    fs::remove(out);
    fs::remove(metrics);
    return s;
  }

  static void expect_metrics(const json& m, bool errors) {
    for (const char* key : {"l2_error", "energy_error"})
      EXPECT_EQ(m.contains(key), errors) << key << " in " << m.dump(2);
    for (const char* key : {"dofs", "cells", "h_avg", "rcond"}) {
      ASSERT_TRUE(m.contains(key)) << "missing key " << key << " in " << m.dump(2);
      ASSERT_TRUE(m[key].is_number()) << key << " is not a number in " << m.dump(2);
      EXPECT_TRUE(std::isfinite(m[key].get<double>())) << key;
      EXPECT_GE(m[key].get<double>(), 0.0) << key;
    }
    EXPECT_GT(m["dofs"].get<int>(), 0);
    EXPECT_GT(m["cells"].get<int>(), 0);
    EXPECT_GT(m["h_avg"].get<double>(), 0.0);
    EXPECT_GT(m["rcond"].get<double>(), 0.0);
    EXPECT_LE(m["rcond"].get<double>(), 1.0);
    ASSERT_TRUE(m.contains("seconds")) << m.dump(2);
    ASSERT_TRUE(m["seconds"].is_object()) << m.dump(2);
    EXPECT_EQ(m["seconds"].contains("error"), errors) << m.dump(2);
    for (const char* stage : {"element", "assembly", "factorization", "solve", "mesh"}) {
      ASSERT_TRUE(m["seconds"].contains(stage))
          << "missing seconds." << stage << " in " << m.dump(2);
      ASSERT_TRUE(m["seconds"][stage].is_number()) << stage;
      const double t = m["seconds"][stage].get<double>();
      EXPECT_TRUE(std::isfinite(t) && t >= 0.0) << stage << " " << t;
    }
    ASSERT_TRUE(m.contains("blas")) << m.dump(2);
    ASSERT_TRUE(m["blas"].is_string());
    EXPECT_FALSE(m["blas"].get<std::string>().empty());
    // Every number anywhere in the file is finite.
    std::function<void(const json&)> finite = [&](const json& j) {
      if (j.is_number()) {
        EXPECT_TRUE(std::isfinite(j.get<double>())) << j.dump();
      }
      if (j.is_object() || j.is_array())
        for (const auto& x : j) finite(x);
    };
    finite(m);
  }

  static void expect_clean_vtu(const std::string& vtu) {
    for (const char* name : {"displacement", "exact_displacement", "mean_stress", "von_mises"})
      EXPECT_NE(vtu.find("Name=\"" + std::string(name) + "\""), std::string::npos)
          << "no field " << name;
    std::string lower = vtu;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    EXPECT_EQ(lower.find("nan"), std::string::npos) << "NaN in the result file";
    EXPECT_EQ(lower.find("inf"), std::string::npos) << "infinity in the result file";
  }

  fs::path dir_, io_;
};

int vtu_attribute(const std::string& vtu, const std::string& name) {
  const std::string key = name + "=\"";
  const auto at = vtu.find(key);
  if (at == std::string::npos) return -1;
  return std::stoi(vtu.substr(at + key.size()));
}

TEST_F(SolveCommand, BeamWritesMetricsAndResult) {
  const Success s = expect_success({"solve", "--family", "hex", "--h", "0.2", "--problem", "beam"});
  if (s.metrics.is_null()) return;
  const json& m = s.metrics;
  EXPECT_EQ(m.value("cells", -1), vtu_attribute(s.vtu, "NumberOfCells"));
  EXPECT_EQ(m.value("dofs", -1), 2 * vtu_attribute(s.vtu, "NumberOfPoints"));
  // Default domain [0,4] x [-0.5,0.5]: h_avg = sqrt(4 / cells).
  EXPECT_NEAR(m["h_avg"].get<double>(), std::sqrt(4.0 / m["cells"].get<double>()), 1e-12);
  EXPECT_GT(m["l2_error"].get<double>(), 1e-5);
  EXPECT_LT(m["l2_error"].get<double>(), 0.05);
  EXPECT_GT(m["energy_error"].get<double>(), m["l2_error"].get<double>());
  EXPECT_LT(m["energy_error"].get<double>(), 0.3);
}

TEST_F(SolveCommand, PlaneStrainMeanDilationAndOptions) {
  const Success s = expect_success({"solve",
                                    "--family",
                                    "rcp",
                                    "--d",
                                    "0.15",
                                    "--seed",
                                    "4",
                                    "--problem",
                                    "beam",
                                    "--plane",
                                    "strain",
                                    "--nu",
                                    "0.4999",
                                    "--mean-dilation",
                                    "--rule",
                                    "1",
                                    "--refinement",
                                    "2",
                                    "--degree",
                                    "2",
                                    "--threads",
                                    "2",
                                    "--domain",
                                    "0,-0.5,4.618802153517006,0.5"});
  if (s.metrics.is_null()) return;
  EXPECT_LT(s.metrics["l2_error"].get<double>(), 0.1);
}

TEST_F(SolveCommand, PatchTestsPass) {
  for (const char* problem : {"patch", "patch-mixed"}) {
    const Success s = expect_success({"solve", "--family", "perturbed-hex", "--h", "0.2", "--r",
                                      "0.4", "--problem", problem, "--domain", "0,0,2,1"});
    if (s.metrics.is_null()) continue;
    EXPECT_LT(s.metrics["l2_error"].get<double>(), 1e-10) << problem;
    EXPECT_LT(s.metrics["energy_error"].get<double>(), 1e-10) << problem;
    const Success u =
        expect_success({"solve", "--family", "perturbed-hex", "--h", "0.2", "--r", "0.4",
                        "--problem", problem, "--domain", "0,0,2,1", "--no-correction"});
    if (u.metrics.is_null()) continue;
    EXPECT_GT(u.metrics["l2_error"].get<double>(), 1e-6) << problem << " without the correction";
  }
}

TEST_F(SolveCommand, PatchTestOnImportedMesh) {
  const Success s = expect_success(
      {"solve", "--mesh", (kData / "good" / "quads_2x2.vtu").string(), "--problem", "patch"});
  if (s.metrics.is_null()) return;
  EXPECT_EQ(s.metrics.value("cells", -1), 4);
  EXPECT_LT(s.metrics["l2_error"].get<double>(), 1e-10);
  EXPECT_LT(s.metrics["energy_error"].get<double>(), 1e-10);
}

TEST_F(SolveCommand, NoErrorsSkipsTheErrorIntegration) {
  const Success s = expect_success(
      {"solve", "--family", "rcp", "--d", "0.2", "--problem", "beam", "--no-errors"}, false);
  if (s.metrics.is_null()) return;
  EXPECT_FALSE(s.metrics["seconds"].contains("error_weights"));
  EXPECT_EQ(s.vtu.find("error_density"), std::string::npos);
  EXPECT_NE(s.vtu.find("Name=\"mean_stress\""), std::string::npos);
}

TEST_F(SolveCommand, ManufacturedSolution) {
  const Success s = expect_success({"solve", "--family", "quad", "--h", "0.1", "--problem", "mms"});
  if (s.metrics.is_null()) return;
  EXPECT_LT(s.metrics["l2_error"].get<double>(), 0.05);
}

TEST_F(SolveCommand, RejectsTheSingularProblem) {
  expect_rejected({"solve", "--family", "hex", "--h", "0.2", "--problem", "patch-traction"});
}

TEST_F(SolveCommand, RejectsBadMaterial) {
  expect_rejected({"solve", "--family", "hex", "--h", "0.2", "--nu", "0.5"}, "nu");
  expect_rejected({"solve", "--family", "hex", "--h", "0.2", "--nu", "-1"}, "nu");
  expect_rejected({"solve", "--family", "hex", "--h", "0.2", "--nu", "0.7"}, "nu");
  expect_rejected({"solve", "--family", "hex", "--h", "0.2", "--E", "0"}, "E");
  expect_rejected({"solve", "--family", "hex", "--h", "0.2", "--E", "-2"}, "E");
}

TEST_F(SolveCommand, RejectsInvalidMesh) {
  for (const char* file : {"clockwise_cell.vtu", "hole.vtu"})
    expect_rejected({"solve", "--mesh", (kData / "invalid" / file).string(), "--problem", "patch"});
  expect_rejected(
      {"solve", "--mesh", (kData / "bad" / "not_xml.vtu").string(), "--problem", "patch"});
  expect_rejected({"solve", "--mesh", (dir_ / "missing.vtu").string(), "--problem", "patch"});
}

TEST_F(SolveCommand, RejectsBeamOnWrongDomain) {
  expect_rejected(
      {"solve", "--family", "hex", "--h", "0.2", "--problem", "beam", "--domain", "0,0,4,1"},
      "beam");
  expect_rejected(
      {"solve", "--family", "hex", "--h", "0.2", "--problem", "beam", "--domain", "1,-0.5,4,0.5"},
      "beam");
}

TEST_F(SolveCommand, RejectsOtherBadOptions) {
  expect_rejected({"solve", "--family", "hex", "--h", "0.2", "--problem", "plate"});
  expect_rejected({"solve", "--family", "hex", "--h", "0.2", "--plane", "shell"});
  expect_rejected({"solve", "--family", "hex", "--h", "0.2", "--rule", "4"});
  expect_rejected({"solve", "--family", "hex", "--h", "0.2", "--formulation", "dg-magic"});
  expect_rejected({"solve", "--family", "pentagons", "--h", "0.2"});
  expect_rejected({"solve", "--family", "hex", "--h", "0.2", "--nu", "abc"});
}

TEST_F(SolveCommand, RejectsMissingOutputFolder) {
  const std::vector<std::string> args = {
      "solve", "--family", "hex", "--h", "0.2", "-o", (dir_ / "no" / "such" / "r.vtu").string()};
  const RunResult r = run(args);
  EXPECT_EQ(r.exit_code, 2) << describe(args, r);
  EXPECT_EQ(r.err_lines(), 1) << describe(args, r);
  EXPECT_TRUE(r.err.starts_with("vorodg: error:")) << describe(args, r);
  EXPECT_FALSE(fs::exists(dir_ / "no"));
}

}  // namespace
}  // namespace vorodg
