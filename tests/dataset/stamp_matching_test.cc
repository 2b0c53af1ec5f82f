#include "dataset/stamp_matching.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <tuple>

namespace dynvo {
namespace {

using Pairs = std::vector<std::pair<size_t, size_t>>;

// associate.py written out literally: all candidates, sorted as (gap, a, b) tuples, greedy.
Pairs ReferenceAssociate(const std::vector<double>& a, const std::vector<double>& b, double max) {
  std::vector<std::tuple<double, double, double, size_t, size_t>> candidates;
  for (size_t i = 0; i < a.size(); ++i)
    for (size_t j = 0; j < b.size(); ++j)
      if (std::abs(a[i] - b[j]) < max) candidates.emplace_back(std::abs(a[i] - b[j]), a[i], b[j], i, j);
  std::sort(candidates.begin(), candidates.end());
  std::set<size_t> used_a, used_b;
  Pairs pairs;
  for (const auto& c : candidates) {
    const size_t i = std::get<3>(c), j = std::get<4>(c);
    if (used_a.count(i) || used_b.count(j)) continue;
    used_a.insert(i);
    used_b.insert(j);
    pairs.emplace_back(i, j);
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

TEST(MatchStamps, NearestWithinMaxDifference) {
  const std::vector<double> rgb = {1.00, 1.10, 1.20, 1.30};
  const std::vector<double> depth = {0.99, 1.115, 1.26, 1.305};
  // 1.20 has no depth within 0.02 (1.26 is 0.06 away); 1.30 takes 1.305.
  EXPECT_EQ(MatchStamps(rgb, depth, 0.02), (Pairs{{0, 0}, {1, 1}, {3, 3}}));
  EXPECT_TRUE(MatchStamps(rgb, depth, 0.001).empty());
  EXPECT_TRUE(MatchStamps({}, depth, 0.02).empty());
  EXPECT_TRUE(MatchStamps(rgb, {}, 0.02).empty());
}

TEST(MatchStamps, OneToOneGreedyBySmallestGap) {
  // Both RGB stamps are nearest to depth 1.00; the closer one (1.004) gets it, the other
  // falls back to its second choice.
  const std::vector<double> rgb = {0.99, 1.004};
  const std::vector<double> depth = {0.975, 1.00};
  EXPECT_EQ(MatchStamps(rgb, depth, 0.02), (Pairs{{0, 0}, {1, 1}}));
  // Without the fallback within range, the farther RGB stamp stays unmatched.
  EXPECT_EQ(MatchStamps(rgb, {1.00}, 0.02), (Pairs{{1, 0}}));
}

TEST(MatchStamps, MaxDifferenceIsStrict) {
  // Gaps exactly representable in binary: 0.25 and 0.5.
  EXPECT_TRUE(MatchStamps({1.0}, {1.25}, 0.25).empty());
  EXPECT_EQ(MatchStamps({1.0}, {1.25}, 0.2500001), (Pairs{{0, 0}}));
  EXPECT_TRUE(MatchStamps({1.5}, {1.0}, 0.5).empty());
}

TEST(MatchStamps, TiesGoToTheLowerStamps) {
  // depth 2.0 is 0.25 from both RGB stamps: associate.py's tuple order picks rgb 1.75.
  EXPECT_EQ(MatchStamps({1.75, 2.25}, {2.0}, 0.5), (Pairs{{0, 0}}));
  // rgb 2.0 is 0.25 from both depth stamps: it picks depth 1.75.
  EXPECT_EQ(MatchStamps({2.0}, {1.75, 2.25}, 0.5), (Pairs{{0, 0}}));
}

TEST(MatchStamps, AgreesWithLiteralAssociateOnRandomStreams) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  std::bernoulli_distribution drop(0.15);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<double> rgb, depth;
    for (int k = 0; k < 60; ++k) {
      if (!drop(rng)) rgb.push_back(k / 30.0 + 0.3 * jitter(rng));
      if (!drop(rng)) depth.push_back(k / 30.0 + jitter(rng));
    }
    std::sort(rgb.begin(), rgb.end());
    std::sort(depth.begin(), depth.end());
    const double max = trial % 2 ? 0.02 : 0.01;
    const Pairs pairs = MatchStamps(rgb, depth, max);
    EXPECT_EQ(pairs, ReferenceAssociate(rgb, depth, max)) << "trial " << trial;
    EXPECT_GT(pairs.size(), 10u);
  }
}

TEST(MatchStamps, UnsortedInputGivesTheSamePairs) {
  const std::vector<double> a = {3.0, 1.0, 2.0};
  const std::vector<double> b = {2.01, 0.995, 3.02};
  EXPECT_EQ(MatchStamps(a, b, 0.05), ReferenceAssociate(a, b, 0.05));
  EXPECT_EQ(MatchStamps(a, b, 0.05), (Pairs{{0, 2}, {1, 1}, {2, 0}}));
}

}  // namespace
}  // namespace dynvo
