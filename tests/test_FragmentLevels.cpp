// The fragment statistics over the levels of a fragmentation study
// (verification/kinds/dynamics/FragmentLevels, docs/fragmentation.md "Over the levels"), on records
// and fragment tables written here:
//   - complete runs only, grouped by (mesh block, level), ordered coarse to fine by h_avg;
//   - per level: the count's mean and sample standard deviation, the largest fragment's mean, the
//     median run time, and the pooled mass fractions (each run's masses over its own total);
//   - the KS distance to the next coarser level: 0 for identical pooled samples, and 2/3 for
//     {1/4, 1/4, 1/2} pooled twice against {1/2, 1/2} pooled three times (below 1/2 the coarse
//     CDF is 4/6 and the fine one 0);
//   - a missing fragment table is an InputError naming the file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/util/Errors.hpp"
#include "verification/kinds/dynamics/FragmentLevels.hpp"

namespace vorodg {
namespace {

namespace fs = std::filesystem;

struct Scratch {
  fs::path dir = fs::temp_directory_path() / ("vorodg_levels_" + std::to_string(getpid()));
  Scratch() { fs::create_directories(dir / "fragments"); }
  ~Scratch() { fs::remove_all(dir); }
};

DynamicsRecord record(const fs::path& dir, const std::string& label, int level, int realization,
                      double h, double seconds, const std::vector<double>& masses) {
  DynamicsRecord r;
  r.run.label = label, r.run.level = level, r.run.realization = realization;
  r.h_avg = h, r.seconds = seconds, r.complete = true;
  r.measures.fragments = static_cast<double>(masses.size());
  double total = 0.0, largest = 0.0;
  for (double m : masses) total += m, largest = std::max(largest, m);
  r.measures.max_fragment_mass_fraction = largest / total;
  std::ofstream f(dir / "fragments" / (r.run.id() + ".csv"));
  f << "fragment,mass,cells,x,y,vx,vy\n";
  for (std::size_t i = 0; i < masses.size(); ++i) f << i << ',' << masses[i] << ",1,0,0,0,0\n";
  return r;
}

TEST(FragmentLevels, GroupsOrdersAndCompares) {
  const Scratch s;
  std::vector<DynamicsRecord> runs = {
      // The fine level first: the order must come from h_avg.
      record(s.dir, "rcp", 1, 0, 0.05, 3.0, {2, 2}),  // fractions 1/2, 1/2
      record(s.dir, "rcp", 1, 1, 0.07, 5.0, {7, 7}),
      record(s.dir, "rcp", 1, 2, 0.06, 4.0, {1, 1}),
      record(s.dir, "rcp", 0, 0, 0.2, 1.0, {1, 1, 2}),  // 1/4, 1/4, 1/2
      record(s.dir, "rcp", 0, 1, 0.2, 2.0, {3, 3, 6}),
  };
  DynamicsRecord failed = record(s.dir, "rcp", 2, 0, 0.01, 9.0, {1});
  failed.complete = false;  // left out: no level 2
  runs.push_back(failed);
  const std::vector<FragmentLevel> levels = fragment_levels(runs, s.dir);
  ASSERT_EQ(levels.size(), 2u);
  EXPECT_EQ(levels[0].level, 0);
  EXPECT_EQ(levels[1].level, 1);
  EXPECT_NEAR(levels[1].h_avg, 0.06, 1e-15);
  EXPECT_DOUBLE_EQ(levels[0].fragments.mean, 3.0);
  EXPECT_DOUBLE_EQ(*levels[0].fragments.std_dev, 0.0);
  EXPECT_DOUBLE_EQ(levels[0].largest.mean, 0.5);
  EXPECT_DOUBLE_EQ(levels[0].median_seconds, 1.5);  // even count: the middle two's mean
  EXPECT_DOUBLE_EQ(levels[1].median_seconds, 4.0);
  EXPECT_EQ(levels[0].mass_fractions.size(), 6u);
  EXPECT_EQ(levels[1].mass_fractions.size(), 6u);
  EXPECT_FALSE(levels[0].against_coarser);
  // Pooled: {1/4 x4, 1/2 x2} against {1/2 x6}. Below 1/2 the coarse CDF is 4/6, the fine one 0.
  ASSERT_TRUE(levels[1].against_coarser);
  EXPECT_NEAR(levels[1].against_coarser->distance, 2.0 / 3.0, 1e-15);
  const std::string csv = fragment_levels_csv(levels);
  EXPECT_NE(csv.find("mesh,level,h_avg,runs,"), std::string::npos);
  EXPECT_NE(fragment_levels_md(levels).find("distinguishable"), std::string::npos);
}

TEST(FragmentLevels, IdenticalLevelsAreAtDistanceZero) {
  const Scratch s;
  const std::vector<DynamicsRecord> runs = {record(s.dir, "a", 0, 0, 0.1, 1.0, {1, 2, 3}),
                                            record(s.dir, "b", 0, 0, 0.05, 1.0, {2, 4, 6})};
  const std::vector<FragmentLevel> levels = fragment_levels(runs, s.dir);
  ASSERT_EQ(levels.size(), 2u);
  EXPECT_EQ(levels[0].mesh, "a");
  EXPECT_DOUBLE_EQ(levels[1].against_coarser->distance, 0.0);
  EXPECT_NE(fragment_levels_md(levels).find("not distinguishable"), std::string::npos);
}

TEST(FragmentLevels, MissingTableNamesTheFile) {
  const Scratch s;
  DynamicsRecord r = record(s.dir, "rcp", 0, 0, 0.1, 1.0, {1});
  fs::remove(s.dir / "fragments" / (r.run.id() + ".csv"));
  try {
    fragment_levels({r}, s.dir);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(r.run.id() + ".csv"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vorodg
