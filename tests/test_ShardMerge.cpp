// `vorodg run ... --shard K/N` and `vorodg merge DIR`: a study split into shards that share one
// output folder, then merged, writes the same summary.json, byte for byte, as one process; a
// merge with a shard missing refuses, naming how many runs lack results; a study of variants
// (one results file per sub-folder) merges too.
#include <gtest/gtest.h>

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

// Three levels, two realizations: 6 meshes (tasks), 18 runs.
const std::string kScene = small_study_scene("sharded", {0.3, 0.2, 0.15}, 2, 11);

class ShardMerge : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_test_dir("vorodg_test_shard");
    std::ofstream(dir_ / "sharded.json") << kScene;
  }
  void TearDown() override { fs::remove_all(dir_); }
  RunResult run(const std::string& scene, const std::string& out, const std::string& shard) const {
    std::vector<std::string> args{"run",     scene,        "-o",        (dir_ / out).string(),
                                  "--quiet", "--no-plots", "--threads", "1"};
    if (!shard.empty()) args.insert(args.end(), {"--shard", shard});
    return run_program(kExe, args, dir_);
  }
  RunResult merge(const std::string& out) const {
    return run_program(kExe, {"merge", (dir_ / out).string(), "--no-plots"}, dir_);
  }
  fs::path dir_;
};

TEST_F(ShardMerge, ShardsThenMergeWriteTheSummaryOfOneProcess) {
  const std::string scene = (dir_ / "sharded.json").string();
  ASSERT_EQ(run(scene, "one", "").exit_code, 0);
  for (const char* shard : {"0/4", "1/4", "2/4", "3/4"}) {
    const RunResult r = run(scene, "split", shard);
    ASSERT_EQ(r.exit_code, 0) << shard << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(dir_ / "split" / "summary.json"));  // a shard writes no report
  EXPECT_TRUE(fs::exists(dir_ / "split" / "results.shard-3-of-4.jsonl"));
  const RunResult r = merge("split");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(slurp(dir_ / "one" / "summary.json"), slurp(dir_ / "split" / "summary.json"));
  // Merging again changes nothing.
  ASSERT_EQ(merge("split").exit_code, 0);
  EXPECT_EQ(slurp(dir_ / "one" / "summary.json"), slurp(dir_ / "split" / "summary.json"));
}

TEST_F(ShardMerge, AMissingShardIsRefused) {
  const std::string scene = (dir_ / "sharded.json").string();
  ASSERT_EQ(run(scene, "split", "0/2").exit_code, 0);
  const RunResult r = merge("split");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("9 runs have no results yet"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_ / "split" / "summary.json"));
}

TEST_F(ShardMerge, BadShardsAndFoldersAreRefused) {
  const std::string scene = (dir_ / "sharded.json").string();
  for (const char* shard : {"2/2", "-1/2", "1", "a/b", "1/0"})
    EXPECT_EQ(run(scene, "bad", shard).exit_code, 2) << shard;
  const RunResult r = merge("nowhere");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("run.json"), std::string::npos) << r.err;
}

TEST_F(ShardMerge, VariantsMergeFolderByFolder) {
  ASSERT_EQ(run("strip-fragmentation-quick", "one", "").exit_code, 0);
  for (const char* shard : {"0/2", "1/2"})
    ASSERT_EQ(run("strip-fragmentation-quick", "split", shard).exit_code, 0) << shard;
  const RunResult r = merge("split");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* variant : {"rate-1e4", "rate-3e4", "rate-1e5"})
    EXPECT_EQ(slurp(dir_ / "one" / variant / "summary.json"),
              slurp(dir_ / "split" / variant / "summary.json"))
        << variant;
}

}  // namespace
}  // namespace vorodg
