#include "eval/error_statistics.h"

#include <cmath>

#include <gtest/gtest.h>

namespace dynvo {
namespace {

TEST(ErrorStatistics, EvenCountLikeNumpy) {
  const ErrorStatistics s = Summarize({4.0, 1.0, 3.0, 2.0});
  EXPECT_EQ(s.count, 4u);
  EXPECT_DOUBLE_EQ(s.rmse, std::sqrt(7.5));  // (16 + 1 + 9 + 4) / 4
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.median, 2.5);           // mean of the two middle values
  EXPECT_DOUBLE_EQ(s.std, std::sqrt(1.25));  // population std, ddof = 0
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.max, 4.0);
}

TEST(ErrorStatistics, OddCountMedianIsMiddleValue) {
  const ErrorStatistics s = Summarize({3.0, 10.0, 1.0});
  EXPECT_DOUBLE_EQ(s.median, 3.0);
  EXPECT_DOUBLE_EQ(s.mean, 14.0 / 3.0);
  EXPECT_DOUBLE_EQ(Median({5.0}), 5.0);
}

TEST(ErrorStatistics, EmptyGivesCountZeroAndNan) {
  const ErrorStatistics s = Summarize({});
  EXPECT_EQ(s.count, 0u);
  EXPECT_TRUE(std::isnan(s.rmse));
  EXPECT_TRUE(std::isnan(s.median));
  EXPECT_TRUE(std::isnan(Median({})));
}

}  // namespace
}  // namespace dynvo
