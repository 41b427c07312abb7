// `vorodg run` end to end: a small scene through the program, the report files it
// writes, a study killed half way and resumed giving the same summary.json as an uninterrupted
// one, and scene validation (unknown keys named with a suggestion, wrong types, bad levels).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "support/RunVorodg.hpp"
#include "support/SmallStudy.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;
namespace fs = std::filesystem;

const fs::path kExe = VORODG_EXE;

const std::string kScene = small_study_scene("tiny", {0.3, 0.15}, 2, 5);

class RunCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("vorodg_test_run_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    std::ofstream(dir_ / "tiny.json") << kScene;
  }
  void TearDown() override { fs::remove_all(dir_); }
  RunResult run(const std::vector<std::string>& args) const {
    return run_program(kExe, args, dir_);
  }
  fs::path dir_;
};

TEST_F(RunCommand, WritesEveryReportFile) {
  const RunResult r = run({"run", (dir_ / "tiny.json").string(), "-o", (dir_ / "out").string(),
                           "--quiet", "--no-plots"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f :
       {"results.jsonl", "results.csv", "summary.json", "timings.json", "report.md"})
    EXPECT_TRUE(fs::exists(dir_ / "out" / f)) << f;
  const auto summary = nlohmann::json::parse(slurp(dir_ / "out" / "summary.json"));
  ASSERT_EQ(summary["groups"].size(), 3u);  // cg, dg-nitsche kp=100, kp=1000
  for (const auto& g : summary["groups"]) {
    EXPECT_EQ(g["levels"].size(), 2u);
    EXPECT_EQ(g["levels"][0]["runs"], 2);
    EXPECT_GT(g["rate_l2"]["value"].get<double>(), 1.0) << g["key"];
  }
  std::ifstream lines(dir_ / "out" / "results.jsonl");
  int n = 0;
  for (std::string line; std::getline(lines, line);) ++n;
  EXPECT_EQ(n, 12);  // 2 levels x 2 realizations x 3 variants
  EXPECT_NE(r.out.find("least-squares rate"), std::string::npos);
  EXPECT_NE(slurp(dir_ / "out" / "report.md").find("| level | h_avg |"), std::string::npos);
}

/// Every line of a results file is a whole record (a resumed run must not glue its first record
/// onto a line a stop cut short: a later resume or merge would lose both).
void expect_every_line_parses(const fs::path& jsonl) {
  std::ifstream in(jsonl);
  int n = 0;
  for (std::string line; std::getline(in, line); ++n) {
    if (line.empty()) continue;
    try {
      (void)nlohmann::json::parse(line).at("id");
    } catch (const nlohmann::json::exception&) {
      // The one cut line a stop may leave stays: it is what the kill wrote, alone on its line.
      EXPECT_EQ(line.find("}{"), std::string::npos) << jsonl << " line " << n + 1;
      EXPECT_EQ(line.find("{\"cells\"", 1), std::string::npos) << jsonl << " line " << n + 1;
    }
  }
}

/// Keeps the first `lines` records of a results file, then what `tail` makes of the next one
/// (the state a kill leaves behind), and removes the summary.
void cut_results(const fs::path& out, int lines,
                 const std::function<std::string(std::string)>& tail) {
  std::ifstream in(out / "results.jsonl");
  std::string kept, line;
  for (int i = 0; i < lines && std::getline(in, line); ++i) kept += line + "\n";
  std::getline(in, line);
  kept += tail(line);
  in.close();
  std::ofstream(out / "results.jsonl", std::ios::trunc) << kept;
  fs::remove(out / "summary.json");
}

TEST_F(RunCommand, AnInterruptedStudyResumesToTheSameSummary) {
  const std::string scene = (dir_ / "tiny.json").string();
  ASSERT_EQ(run({"run", scene, "-o", (dir_ / "whole").string(), "--quiet", "--no-plots"}).exit_code,
            0);
  const std::string whole = slurp(dir_ / "whole" / "summary.json");
  // A kill during a run leaves the finished lines and possibly half a line, or a whole record
  // without its newline: model both exactly.
  const std::pair<std::string, std::function<std::string(std::string)>> stops[] = {
      {"half", [](std::string l) { return l.substr(0, l.size() / 2); }},
      {"unended", [](std::string l) { return l; }}};
  for (const auto& [name, tail] : stops) {
    const fs::path out = dir_ / name;
    ASSERT_EQ(run({"run", scene, "-o", out.string(), "--quiet", "--no-plots"}).exit_code, 0);
    cut_results(out, 5, tail);
    const RunResult again = run({"run", scene, "-o", out.string(), "--quiet", "--no-plots"});
    ASSERT_EQ(again.exit_code, 0) << name << ": " << again.err;
    EXPECT_EQ(whole, slurp(out / "summary.json")) << name;
    expect_every_line_parses(out / "results.jsonl");
  }
  // And a real kill at an arbitrary moment, then a rerun.
  const std::string killed = "timeout -s KILL 0.7 " + quote(kExe.string()) + " run " +
                             quote(scene) + " -o " + quote((dir_ / "killed").string()) +
                             " --quiet --no-plots >/dev/null 2>&1";
  [[maybe_unused]] const int status = std::system(killed.c_str());
  const std::string left = fs::exists(dir_ / "killed" / "results.jsonl")
                               ? slurp(dir_ / "killed" / "results.jsonl")
                               : std::string("(no results file)");
  const RunResult again =
      run({"run", scene, "-o", (dir_ / "killed").string(), "--quiet", "--no-plots"});
  ASSERT_EQ(again.exit_code, 0) << again.err << "\nthe kill left:\n" << left;
  EXPECT_EQ(whole, slurp(dir_ / "killed" / "summary.json")) << "the kill left:\n" << left;
  expect_every_line_parses(dir_ / "killed" / "results.jsonl");
}

TEST_F(RunCommand, ResultsDoNotDependOnTheThreadCount) {
  const std::string scene = (dir_ / "tiny.json").string();
  ASSERT_EQ(
      run({"run", scene, "-o", (dir_ / "one").string(), "--threads", "1", "--quiet", "--no-plots"})
          .exit_code,
      0);
  ASSERT_EQ(
      run({"run", scene, "-o", (dir_ / "two").string(), "--threads", "2", "--quiet", "--no-plots"})
          .exit_code,
      0);
  EXPECT_EQ(slurp(dir_ / "one" / "summary.json"), slurp(dir_ / "two" / "summary.json"));
}

TEST_F(RunCommand, BadScenesAreRefusedWithTheKeyNamed) {
  struct Case {
    std::string text, mention;
  };
  const Case cases[] = {
      {R"({"meshes": [{"sizes": [0.1]}], "formulatons": []})", "did you mean 'formulations'"},
      {R"({"meshes": [{"sizes": "0.1"}], "formulations": [{"name": "cg"}]})", "meshes[0].sizes"},
      {R"({"meshes": [{"sizes": [0.1, 0.2]}], "formulations": [{"name": "cg"}]})",
       "coarse to fine"},
      {R"({"meshes": [{"sizes": [0.1], "realizations": 0}], "formulations": [{"name": "cg"}]})",
       "realizations"},
      {R"({"meshes": [{"sizes": [0.1]}], "formulations": [{"name": "dg-nitsche", "kp": [0]}]})",
       "kp"},
      {R"({"meshes": [{"sizes": [0.1]}], "formulations": [{"name": "cg"}], "material": {"nu": 0.5}})",
       "material.nu"},
      {R"({"meshes": [{"sizes": [0.1]}], "formulations": [{"name": "cg"}])", "not valid JSON"},
  };
  for (const Case& c : cases) {
    std::ofstream(dir_ / "bad.json", std::ios::trunc) << c.text;
    const RunResult r =
        run({"run", (dir_ / "bad.json").string(), "-o", (dir_ / "bad_out").string(), "--quiet"});
    EXPECT_EQ(r.exit_code, 2) << c.text << "\n" << r.err;
    EXPECT_EQ(r.err_lines(), 1) << r.err;
    EXPECT_NE(r.err.find(c.mention), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("bad.json"), std::string::npos) << r.err;
  }
}

TEST_F(RunCommand, TradeOffStudyWritesItsParetoFrontAndChecksItsRecommendation) {
  // min_seconds 0: every level is timed (these runs are far too short to time honestly; the
  // timing rule itself is tested in test_TradeoffAnalysis).
  std::ofstream(dir_ / "tradeoff.json") << R"({
    "study": "trade-off",
    "meshes": [{"family": "rcp", "sizes": [0.3, 0.2, 0.15], "seed": 3}],
    "formulations": [{"name": "cg"}, {"name": "cg", "rule": 1, "label": "one point"}],
    "tradeoff": {"min_seconds": 0, "rate_tolerance": 0.5, "targets": [1e-2, 3e-3],
                 "verification_realizations": 2}
  })";
  const std::vector<std::string> args = {"run",     (dir_ / "tradeoff.json").string(),
                                         "-o",      (dir_ / "t").string(),
                                         "--quiet", "--no-plots"};
  const RunResult r = run(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto data = nlohmann::json::parse(slurp(dir_ / "t" / "tradeoff.json"));
  EXPECT_EQ(data["points"].size(), 6u);  // 2 configurations x 3 levels
  ASSERT_EQ(data["configs"].size(), 2u);
  ASSERT_FALSE(data["pareto"].empty());
  // The front is cheapest first, strictly more accurate at every step, admitted and timed.
  for (std::size_t i = 0; i < data["pareto"].size(); ++i) {
    EXPECT_TRUE(data["pareto"][i]["admitted"].get<bool>());
    EXPECT_TRUE(data["pareto"][i]["timed"].get<bool>());
    if (i == 0) continue;
    EXPECT_GE(data["pareto"][i]["seconds"].get<double>(),
              data["pareto"][i - 1]["seconds"].get<double>());
    EXPECT_LT(data["pareto"][i]["l2_error"].get<double>(),
              data["pareto"][i - 1]["l2_error"].get<double>());
  }
  // The targets as given, largest first; the smallest was run again at its predicted size.
  ASSERT_EQ(data["targets"].size(), 2u);
  EXPECT_EQ(data["targets"][0]["error"].get<double>(), 1e-2);
  ASSERT_TRUE(data["check"].contains("seconds")) << data["check"].dump();
  EXPECT_EQ(data["check"]["runs"].get<int>(), 2);
  EXPECT_EQ(data["check"]["target"].get<double>(), 3e-3);
  const std::string report = slurp(dir_ / "t" / "report.md");
  for (const char* section : {"Which configurations converge", "What accuracy costs",
                              "Pareto front", "Recommendation", "Check of the recommendation"})
    EXPECT_NE(report.find(section), std::string::npos) << section;
  // Wall times never reach the summary: it stays deterministic.
  EXPECT_EQ(slurp(dir_ / "t" / "summary.json").find("seconds"), std::string::npos);
  // A rerun resumes: the study's and the check's runs are all found, none run again.
  const std::string check_runs = slurp(dir_ / "t" / "verification" / "results.jsonl");
  ASSERT_EQ(run(args).exit_code, 0);
  EXPECT_EQ(slurp(dir_ / "t" / "verification" / "results.jsonl"), check_runs);
}

TEST_F(RunCommand, PenaltyAnalysisCoversEveryElementOfTheScene) {
  std::ofstream(dir_ / "penalty.json") << R"({
    "study": "penalty-sweep",
    "meshes": [{"family": "rcp", "sizes": [0.4], "seed": 3}],
    "formulations": [{"name": "dg-sipg", "kp": [1]},
                     {"name": "dg-sipg", "kp": [1], "element": "vem", "label": "sipg vem"}]
  })";
  const RunResult r = run({"run", (dir_ / "penalty.json").string(), "-o", (dir_ / "p").string(),
                           "--quiet", "--no-plots"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(dir_ / "p" / "penalty_thresholds.csv");
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line,
            "mesh,level,cells,h_avg,element,traction,auto_median,auto_max,"
            "smallest_definite_kp");
  int rk = 0, vem = 0;
  while (std::getline(in, line)) {
    rk += line.find(",rk,") != std::string::npos;
    vem += line.find(",vem,") != std::string::npos;
  }
  EXPECT_EQ(rk, 3);  // one row per traction kind
  EXPECT_EQ(vem, 3);
}

TEST_F(RunCommand, ListsTheShippedScenes) {
  const RunResult r = run({"run", "--list"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("demo"), std::string::npos);
  EXPECT_NE(r.out.find("patch-suite"), std::string::npos);
  EXPECT_NE(r.out.find("fracture: Petersson's notched three-point-bend beam"), std::string::npos);
}

TEST_F(RunCommand, ThePatchSuiteMeetsItsExpectations) {
  const RunResult r =
      run({"run", "patch-suite", "-o", (dir_ / "patch").string(), "--quiet", "--no-plots"});
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(r.out.find("UNEXPECTED"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace vorodg
