#include "eval/stamp_association.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"

namespace dynvo {
namespace {

// Literal O(N * M) transcription of associate.py, to compare the windowed version against.
std::vector<std::pair<std::size_t, std::size_t>> ReferenceAssociate(const std::vector<double>& first,
                                                                    const std::vector<double>& second, double offset,
                                                                    double max_difference) {
  std::vector<std::tuple<double, double, double, std::size_t, std::size_t>> candidates;
  for (std::size_t a = 0; a < first.size(); ++a)
    for (std::size_t b = 0; b < second.size(); ++b)
      if (std::abs(first[a] - (second[b] + offset)) < max_difference)
        candidates.emplace_back(std::abs(first[a] - (second[b] + offset)), first[a], second[b], a, b);
  std::sort(candidates.begin(), candidates.end());
  std::vector<bool> used_a(first.size()), used_b(second.size());
  std::vector<std::pair<std::size_t, std::size_t>> matches;
  for (const auto& [gap, sa, sb, a, b] : candidates) {
    if (used_a[a] || used_b[b]) continue;
    used_a[a] = used_b[b] = true;
    matches.emplace_back(a, b);
  }
  std::sort(matches.begin(), matches.end());
  return matches;
}

std::vector<std::pair<std::size_t, std::size_t>> AsPairs(const std::vector<StampMatch>& m) {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (const StampMatch& x : m) pairs.emplace_back(x.first, x.second);
  return pairs;
}

using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;

TEST(StampAssociation, OffsetShiftsSecondStamps) {
  const auto m = AssociateStamps({1.0, 2.0, 3.0}, {0.5, 1.5, 2.5}, 0.5, 0.02);
  EXPECT_EQ(AsPairs(m), (Pairs{{0, 0}, {1, 1}, {2, 2}}));
  EXPECT_TRUE(AssociateStamps({1.0, 2.0, 3.0}, {0.5, 1.5, 2.5}, 0.0, 0.02).empty());
}

TEST(StampAssociation, MaxDifferenceIsExclusive) {
  // Dyadic values: the gaps are exact.
  EXPECT_TRUE(AssociateStamps({1.0}, {1.25}, 0.0, 0.25).empty());
  EXPECT_EQ(AsPairs(AssociateStamps({1.0}, {1.125}, 0.0, 0.25)), (Pairs{{0, 0}}));
}

TEST(StampAssociation, GreedyBySmallestGapOneToOne) {
  // Candidates by gap: (f1,s1) 1/32, (f1,s0) 1/16, (f0,s0) 3/16, (f0,s1) 7/32.
  // s0's nearest is f1, but f1 goes to s1 first; s0 then takes f0.
  const auto m = AssociateStamps({1.0, 1.25}, {1.1875, 1.21875}, 0.0, 0.25);
  EXPECT_EQ(AsPairs(m), (Pairs{{0, 0}, {1, 1}}));
  // Each stamp used once: three second stamps near one first stamp give one match.
  EXPECT_EQ(AsPairs(AssociateStamps({2.0}, {1.9375, 2.0, 2.0625}, 0.0, 0.25)), (Pairs{{0, 1}}));
}

TEST(StampAssociation, TiesGoToSmallerStamps) {
  // Equal gaps 0.25: sorted (gap, a, b) takes the smaller first stamp, then smaller second.
  EXPECT_EQ(AsPairs(AssociateStamps({1.0, 1.5}, {1.25}, 0.0, 0.5)), (Pairs{{0, 0}}));
  EXPECT_EQ(AsPairs(AssociateStamps({1.25}, {1.0, 1.5}, 0.0, 0.5)), (Pairs{{0, 0}}));
}

TEST(StampAssociation, MatchesLiteralScriptOnJitteredStreams) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-0.012, 0.012);
  std::bernoulli_distribution drop(0.1);
  std::vector<double> first, second;
  for (int k = 0; k < 600; ++k)
    if (!drop(rng)) first.push_back(100.0 + k * 0.01 + jitter(rng) * 0.3);
  for (int k = 0; k < 200; ++k)
    if (!drop(rng)) second.push_back(100.0 + k * 0.0333 + jitter(rng));
  for (double offset : {0.0, 0.004, -0.011}) {
    const auto m = AssociateStamps(first, second, offset, 0.02);
    EXPECT_EQ(AsPairs(m), ReferenceAssociate(first, second, offset, 0.02)) << offset;
    EXPECT_GT(m.size(), 150u);
  }
}

TEST(StampAssociation, RejectsBadInput) {
  EXPECT_THROW(AssociateStamps({1.0, 1.0}, {1.0}, 0.0, 0.02), InputError);
  EXPECT_THROW(AssociateStamps({1.0}, {2.0, 1.0}, 0.0, 0.02), InputError);
  EXPECT_THROW(AssociateStamps({1.0}, {1.0}, 0.0, 0.0), InputError);
}

}  // namespace
}  // namespace dynvo
