#include "eval/closest_index.h"

#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"

namespace dynvo {
namespace {

TEST(ClosestIndex, ExactHitsAndEnds) {
  const std::vector<double> values{0.0, 1.0, 2.0, 3.0, 10.0};
  for (std::size_t k = 0; k < values.size(); ++k) {
    EXPECT_EQ(BenchmarkClosestIndex(values, values[k]), k);
    EXPECT_EQ(NearestIndex(values, values[k]), k);
  }
  EXPECT_EQ(BenchmarkClosestIndex(values, -5.0), 0u);
  EXPECT_EQ(NearestIndex(values, -5.0), 0u);
  EXPECT_EQ(BenchmarkClosestIndex(values, 99.0), 4u);
  EXPECT_EQ(NearestIndex(values, 99.0), 4u);
  EXPECT_EQ(BenchmarkClosestIndex(values, 7.0), 4u);
  EXPECT_EQ(NearestIndex(values, 6.0), 3u);
}

TEST(ClosestIndex, BenchmarkBreaksTiesByVisitOrder) {
  // find_closest_index([0,1,2,3], 1.5) visits index 2 first (|0.5| < |1.5|), then index 1
  // (|0.5| is not < |0.5|): it returns 2. The true-nearest lookup takes the lower index.
  const std::vector<double> values{0.0, 1.0, 2.0, 3.0};
  EXPECT_EQ(BenchmarkClosestIndex(values, 1.5), 2u);
  EXPECT_EQ(NearestIndex(values, 1.5), 1u);
  EXPECT_EQ(ClosestIndex(values, 1.5, ClosestLookup::kBenchmark), 2u);
  EXPECT_EQ(ClosestIndex(values, 1.5, ClosestLookup::kNearest), 1u);
  // Visit order 2 (|0.5|, best), then 3 (|0.5|, not better): 2, as nearest.
  EXPECT_EQ(BenchmarkClosestIndex(values, 2.5), 2u);
  EXPECT_EQ(NearestIndex(values, 2.5), 2u);
}

TEST(ClosestIndex, BenchmarkEqualsNearestWithoutTies) {
  // The binary search visits both neighbours of the insertion point, so away from exact ties
  // it returns the nearest element.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> gap(0.001, 1.0), where(-2.0, 400.0);
  std::vector<double> values{0.0};
  for (int k = 0; k < 500; ++k) values.push_back(values.back() + gap(rng));
  for (int trial = 0; trial < 5000; ++trial) {
    const double t = where(rng);
    ASSERT_EQ(BenchmarkClosestIndex(values, t), NearestIndex(values, t)) << "t = " << t;
  }
}

TEST(ClosestIndex, EmptyListThrowsAndNamesAreCliSpellings) {
  EXPECT_THROW(BenchmarkClosestIndex({}, 1.0), InputError);
  EXPECT_THROW(NearestIndex({}, 1.0), InputError);
  EXPECT_EQ(ClosestLookupName(ClosestLookup::kBenchmark), "benchmark");
  EXPECT_EQ(ClosestLookupName(ClosestLookup::kNearest), "nearest");
}

}  // namespace
}  // namespace dynvo
