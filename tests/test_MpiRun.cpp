// `mpirun -n N vorodg run` end to end: a study across 2 and 3 ranks (3 oversubscribes this
// machine) writes the same summary.json, byte for byte, as one process; so does a study of
// several variants (one task pool after another); and a job killed half way and run again
// completes to the same summary. Built only with MPI (VORODG_MPI).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/RunVorodg.hpp"
#include "support/SmallStudy.hpp"
#include "support/TestDir.hpp"

namespace vorodg {
namespace {

using namespace vorodg::testing;
namespace fs = std::filesystem;

const fs::path kExe = VORODG_EXE;

// Four levels, three realizations, CG and two DG penalties: 36 runs in 12 tasks, a few seconds.
const std::string kScene = small_study_scene("small", {0.3, 0.15, 0.075, 0.05}, 3, 7);

class MpiRun : public ::testing::Test {
 protected:
  void SetUp() override {
#ifdef VORODG_SANITIZED
    GTEST_SKIP() << "Open MPI's own allocations are not sanitizer-clean";
#endif
    // Open MPI refuses to run as root unless told twice (CI runs as root).
    ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
    ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
    dir_ = fresh_test_dir("vorodg_test_mpi");
    std::ofstream(dir_ / "small.json") << kScene;
  }
  void TearDown() override {
    fs::remove_all(dir_);
  }
  /// `vorodg run SCENE -o DIR` on `ranks` MPI processes (0: no mpirun at all).
  RunResult run(int ranks, const std::string& scene, const std::string& out) const {
    std::vector<std::string> args{"run",     scene,        "-o",        (dir_ / out).string(),
                                  "--quiet", "--no-plots", "--threads", "1"};
    if (ranks == 0) return run_program(kExe, args, dir_);
    args.insert(args.begin(), {"-n", std::to_string(ranks), "--oversubscribe", kExe.string()});
    return run_program("mpirun", args, dir_);
  }
  std::string summary(const std::string& out, const std::string& sub = "") const {
    return slurp(dir_ / out / sub / "summary.json");
  }
  fs::path dir_;
};

TEST_F(MpiRun, TwoAndThreeRanksWriteTheSameSummaryAsOneProcess) {
  const std::string scene = (dir_ / "small.json").string();
  ASSERT_EQ(run(0, scene, "one").exit_code, 0);
  for (int ranks : {2, 3}) {
    const std::string out = "ranks" + std::to_string(ranks);
    const RunResult r = run(ranks, scene, out);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(summary("one"), summary(out)) << ranks << " ranks";
    // The coordinator alone writes results.jsonl: one line per run, no run twice.
    std::ifstream lines(dir_ / out / "results.jsonl");
    int n = 0;
    for (std::string line; std::getline(lines, line);) ++n;
    EXPECT_EQ(n, 36) << ranks << " ranks";
  }
}

TEST_F(MpiRun, VariantsRunOnePoolAfterAnother) {
  // Three variants, one run each: a rank told one pool is done asks for the next at once.
  ASSERT_EQ(run(0, "strip-fragmentation-quick", "one").exit_code, 0);
  const RunResult r = run(3, "strip-fragmentation-quick", "three");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* variant : {"rate-1e4", "rate-3e4", "rate-1e5"})
    EXPECT_EQ(summary("one", variant), summary("three", variant)) << variant;
}

TEST_F(MpiRun, AJobKilledHalfWayCompletesToTheSameSummary) {
  const std::string scene = (dir_ / "small.json").string();
  ASSERT_EQ(run(0, scene, "whole").exit_code, 0);
  // Started in the background and killed once a few runs are in, whatever the machine's speed.
  const fs::path pid_file = dir_ / "pid", results = dir_ / "killed" / "results.jsonl";
  const std::string start = "mpirun -n 2 --oversubscribe " + quote(kExe.string()) + " run " +
                            quote(scene) + " -o " + quote((dir_ / "killed").string()) +
                            " --quiet --no-plots --threads 1 >/dev/null 2>&1 & echo $! > " +
                            quote(pid_file.string());
  ASSERT_EQ(std::system(start.c_str()), 0);
  const auto lines = [&] {
    std::ifstream in(results);
    int n = 0;
    for (std::string line; std::getline(in, line);) ++n;
    return n;
  };
  for (int wait = 0; wait < 1200 && lines() < 6; ++wait) ::usleep(50000);
  const int at_kill = lines();
  const std::string kill = "kill -KILL $(cat " + quote(pid_file.string()) + ")";
  ASSERT_EQ(std::system(kill.c_str()), 0);
  ::sleep(1);  // the ranks see their launcher gone and stop
  ASSERT_GE(at_kill, 6);
  ASSERT_LT(at_kill, 36) << "the job finished before the kill";
  const RunResult r = run(2, scene, "killed");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(summary("whole"), summary("killed"));
}

TEST_F(MpiRun, AnErrorOnEveryRankEndsTheJob) {
  // A scene that cannot be read: every rank refuses it, and the job ends with the input-error
  // code instead of leaving a rank waiting.
  std::ofstream(dir_ / "bad.json") << R"({"name": "bad", "study": "convergence"})";
  const RunResult r = run(2, (dir_ / "bad.json").string(), "bad");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("vorodg: error:"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace vorodg
