// The Hamming distance between two runs' crack histories (fracture/CrackHistory): a worked
// example by hand, identical runs at distance 0 throughout, agreement with a brute-force count of
// the symmetric difference on random histories (fixed seed), and refusal of an edge that cracks
// twice.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "core/util/Errors.hpp"
#include "fracture/CrackHistory.hpp"

namespace vorodg {
namespace {

using Events = std::vector<CrackEvent>;

TEST(CrackHistory, AWorkedExample) {
  const Events a{{1, 5}, {3, 7}, {3, 8}}, b{{1, 5}, {2, 7}, {4, 9}};
  const std::vector<DistanceAtStep> h = hamming_history(a, b);
  ASSERT_EQ(h.size(), 4u);
  const long steps[4] = {1, 2, 3, 4};
  const int distances[4] = {0, 1, 1, 2};  // {5}|{5}; {5}|{5,7}; {5,7,8}|{5,7}; {5,7,8}|{5,7,9}
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(h[i].step, steps[i]);
    EXPECT_EQ(h[i].distance, distances[i]) << "after step " << steps[i];
  }
}

TEST(CrackHistory, IdenticalRunsStayAtZero) {
  const Events a{{4, 1}, {4, 2}, {9, 3}};
  for (const DistanceAtStep& d : hamming_history(a, a)) EXPECT_EQ(d.distance, 0);
  EXPECT_TRUE(hamming_history({}, {}).empty());
}

TEST(CrackHistory, AgreesWithTheSymmetricDifference) {
  std::mt19937 rng(2008);
  for (int trial = 0; trial < 20; ++trial) {
    Events runs[2];
    for (Events& run : runs) {
      std::vector<int> edges(40);
      for (int e = 0; e < 40; ++e) edges[e] = e;
      std::shuffle(edges.begin(), edges.end(), rng);
      const int count = std::uniform_int_distribution<int>(0, 40)(rng);
      for (int i = 0; i < count; ++i)
        run.push_back({std::uniform_int_distribution<long>(0, 30)(rng), edges[i]});
    }
    for (const DistanceAtStep& d : hamming_history(runs[0], runs[1])) {
      std::set<int> cracked[2];
      for (int r = 0; r < 2; ++r)
        for (const auto& e : runs[r])
          if (e.step <= d.step) cracked[r].insert(e.edge);
      int differ = 0;
      for (int e = 0; e < 40; ++e) differ += cracked[0].count(e) != cracked[1].count(e);
      EXPECT_EQ(d.distance, differ) << "trial " << trial << ", step " << d.step;
    }
  }
}

TEST(CrackHistory, RefusesAnEdgeThatCracksTwice) {
  EXPECT_THROW(hamming_history({{1, 3}, {2, 3}}, {}), InputError);
}

}  // namespace
}  // namespace vorodg
