#include "eval/streamed_statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace dynvo {
namespace {

// The pass over two series held in vectors (the test's truth), counting the passes.
ValuePass PassOver(const std::vector<double>& a, const std::vector<double>& b, int* passes) {
  return [&a, &b, passes](const std::function<void(const double*)>& sink) {
    ++*passes;
    for (size_t k = 0; k < a.size(); ++k) {
      const double v[2] = {a[k], b[k]};
      sink(v);
    }
  };
}

void ExpectSame(const ErrorStatistics& streamed, const ErrorStatistics& truth) {
  EXPECT_EQ(streamed.count, truth.count);
  EXPECT_EQ(streamed.median, truth.median);  // exact: the same values selected
  EXPECT_EQ(streamed.min, truth.min);
  EXPECT_EQ(streamed.max, truth.max);
  EXPECT_NEAR(streamed.mean, truth.mean, 1e-12 * std::abs(truth.mean) + 1e-15);
  EXPECT_NEAR(streamed.rmse, truth.rmse, 1e-12 * truth.rmse + 1e-15);
  EXPECT_NEAR(streamed.std, truth.std, 1e-12 * truth.std + 1e-15);
}

TEST(SummarizeStreamed, EqualsSummarizeWhileHoldingFewValues) {
  std::mt19937_64 rng(3);
  std::lognormal_distribution<double> skewed(-3.0, 1.0);  // like RPE errors: long right tail
  std::uniform_real_distribution<double> uniform(0.0, 5.0);
  for (size_t count : {1u, 2u, 7u, 1000u, 1001u}) {
    std::vector<double> a(count), b(count);
    for (size_t k = 0; k < count; ++k) a[k] = skewed(rng), b[k] = uniform(rng);
    int passes = 0;
    // 16 bins and 5 values held: the histogram must narrow several times.
    const std::vector<ErrorStatistics> s = SummarizeStreamed(2, PassOver(a, b, &passes), {16, 5});
    ExpectSame(s[0], Summarize(a));
    ExpectSame(s[1], Summarize(b));
    if (count == 1000) {
      EXPECT_GT(passes, 4) << "narrowed over several passes";
    }
  }
}

TEST(SummarizeStreamed, RepeatedAndEqualValuesAndNoValues) {
  std::vector<double> a = {2, 2, 2, 2, 2}, b = {0, 1, 1, 1, 1};  // a constant series; a tie at the median
  for (int k = 0; k < 200; ++k) a.push_back(2), b.push_back(1);
  int passes = 0;
  const std::vector<ErrorStatistics> s = SummarizeStreamed(2, PassOver(a, b, &passes), {8, 3});
  ExpectSame(s[0], Summarize(a));
  ExpectSame(s[1], Summarize(b));
  const std::vector<double> none;
  const std::vector<ErrorStatistics> empty = SummarizeStreamed(2, PassOver(none, none, &passes));
  EXPECT_EQ(empty[0].count, 0u);
  EXPECT_TRUE(std::isnan(empty[0].median));
}

}  // namespace
}  // namespace dynvo
