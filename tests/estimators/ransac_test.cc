// The generic RANSAC loop on a line fit whose truth is known: 2-point samples, residuals as
// squared vertical distances. It finds the line among 60% outliers, marks exactly the inliers,
// refits on them, stops early when the data are clean, is deterministic for a seed, and reports
// degenerate data as not found.

#include "estimators/ransac.h"

#include <random>

#include <gtest/gtest.h>

#include "core/error.h"

namespace dynvo {
namespace {

struct Line {
  double slope = 0.0, offset = 0.0;
};

// y = slope x + offset through the sampled points; the refit is least squares.
struct LineEstimator {
  using Model = Line;
  static constexpr int kMinSamples = 2;
  std::vector<double> x, y;
  mutable int refits = 0;

  bool Estimate(const std::vector<int>& s, Line* line) const {
    const double dx = x[s[1]] - x[s[0]];
    if (std::abs(dx) < 1e-9) return false;
    line->slope = (y[s[1]] - y[s[0]]) / dx;
    line->offset = y[s[0]] - line->slope * x[s[0]];
    return true;
  }
  void Residuals(const Line& line, std::vector<double>* squared) const {
    squared->resize(x.size());
    for (size_t i = 0; i < x.size(); ++i) {
      const double e = y[i] - (line.slope * x[i] + line.offset);
      (*squared)[i] = e * e;
    }
  }
  bool Refit(const std::vector<int>& inliers, Line* line) const {
    ++refits;
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (int i : inliers) {
      sx += x[i];
      sy += y[i];
      sxx += x[i] * x[i];
      sxy += x[i] * y[i];
    }
    const double n = static_cast<double>(inliers.size());
    const double det = n * sxx - sx * sx;
    if (std::abs(det) < 1e-12) return false;
    line->slope = (n * sxy - sx * sy) / det;
    line->offset = (sy - line->slope * sx) / n;
    return true;
  }
};

// 100 points: the first 40 on y = 2x + 1 with noise of at most 0.05, the rest anywhere.
LineEstimator NoisyLine(unsigned seed) {
  LineEstimator e;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < 100; ++i) {
    const double x = 10.0 * unit(rng);
    e.x.push_back(x);
    e.y.push_back(i < 40 ? 2.0 * x + 1.0 + 0.05 * unit(rng) : 30.0 * unit(rng));
  }
  return e;
}

TEST(Ransac, FindsTheLineAmongOutliersAndMarksItsInliers) {
  const LineEstimator e = NoisyLine(3);
  RansacOptions options;
  options.max_error = 0.2;
  options.max_iterations = 1000;
  const RansacResult<Line> r = RunRansac(e, 100, options);
  ASSERT_TRUE(r.found);
  EXPECT_NEAR(r.model.slope, 2.0, 0.02);
  EXPECT_NEAR(r.model.offset, 1.0, 0.05);
  ASSERT_EQ(r.inliers.size(), 100u);
  for (int i = 0; i < 40; ++i) EXPECT_EQ(r.inliers[i], 1) << i;
  EXPECT_EQ(r.num_inliers, 40 + std::count(r.inliers.begin() + 40, r.inliers.end(), 1));
  EXPECT_LE(r.num_inliers, 44);  // an outlier may fall near the line by chance, a few at most
  EXPECT_GE(e.refits, 1);
  EXPECT_LT(r.iterations, 1000);  // stopped once confident, well before the cap
}

TEST(Ransac, TheSameSeedGivesTheSameModelAndAnotherSeedTheSameLine) {
  const LineEstimator e = NoisyLine(5);
  RansacOptions options;
  options.max_error = 0.2;
  const RansacResult<Line> a = RunRansac(e, 100, options), b = RunRansac(e, 100, options);
  EXPECT_EQ(a.model.slope, b.model.slope);
  EXPECT_EQ(a.model.offset, b.model.offset);
  EXPECT_EQ(a.iterations, b.iterations);
  options.seed = 99;
  const RansacResult<Line> c = RunRansac(e, 100, options);
  EXPECT_NEAR(c.model.slope, 2.0, 0.02);
}

// `n` points (x_i, y_i) = (x(i), y(i)).
template <typename X, typename Y>
LineEstimator Points(int n, X x, Y y) {
  LineEstimator e;
  for (int i = 0; i < n; ++i) {
    e.x.push_back(x(i));
    e.y.push_back(y(i));
  }
  return e;
}

TEST(Ransac, CleanDataStopsAtOnce) {
  const LineEstimator e = Points(
      50, [](int i) { return double(i); }, [](int i) { return 3.0 * i - 2.0; });
  const RansacResult<Line> r = RunRansac(e, 50, RansacOptions{/*max_error=*/0.01});
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.num_inliers, 50);
  EXPECT_EQ(r.iterations, 1);
}

TEST(Ransac, DegenerateOrTooFewDataAreNotFound) {
  const LineEstimator same_x = Points(
      10, [](int) { return 1.0; }, [](int i) { return double(i); });
  RansacOptions options;
  options.max_iterations = 50;
  const RansacResult<Line> degenerate = RunRansac(same_x, 10, options);
  EXPECT_FALSE(degenerate.found);
  EXPECT_EQ(degenerate.num_inliers, 0);
  EXPECT_EQ(degenerate.iterations, 50);
  EXPECT_FALSE(RunRansac(NoisyLine(1), 1, options).found);  // fewer than a sample
}

TEST(Ransac, IterationsNeededFollowTheStandardFormula) {
  EXPECT_EQ(RansacIterationsNeeded(1.0, 4, 0.99, 500), 1);
  EXPECT_EQ(RansacIterationsNeeded(0.0, 4, 0.99, 500), 500);
  // (1 - 0.5^2)^k <= 0.01 -> k = ceil(log 0.01 / log 0.75) = 17.
  EXPECT_EQ(RansacIterationsNeeded(0.5, 2, 0.99, 500), 17);
  EXPECT_EQ(RansacIterationsNeeded(0.1, 4, 0.999, 500), 500);  // capped
}

TEST(Ransac, OptionsCheckNamesTheField) {
  RansacOptions options;
  options.max_error = 0.0;
  try {
    options.Check("homography");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("homography.max_error must be > 0", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace dynvo
