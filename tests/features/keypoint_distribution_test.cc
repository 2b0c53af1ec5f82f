#include "features/keypoint_distribution.h"

#include <algorithm>
#include <random>
#include <set>

#include <gtest/gtest.h>

namespace dynvo {
namespace {

// 2000 keypoints in the top-left 100x100 pixels (strong), 200 spread over 640x480 (weak).
std::vector<cv::KeyPoint> Clustered() {
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> corner(0.f, 100.f), ux(0.f, 640.f), uy(0.f, 480.f);
  std::vector<cv::KeyPoint> keypoints;
  for (int i = 0; i < 2000; ++i)
    keypoints.emplace_back(cv::Point2f(corner(rng), corner(rng)), 7.f, -1.f, 50.f + i % 50);
  for (int i = 0; i < 200; ++i) keypoints.emplace_back(cv::Point2f(ux(rng), uy(rng)), 7.f, -1.f, 10.f + i % 10);
  return keypoints;
}

// Number of cells of an 8x6 grid over 640x480 holding at least one of `indices`.
int CellsCovered(const std::vector<cv::KeyPoint>& keypoints, const std::vector<int>& indices) {
  std::set<int> cells;
  for (int i : indices)
    cells.insert(static_cast<int>(keypoints[i].pt.y / 80) * 8 + static_cast<int>(keypoints[i].pt.x / 80));
  return static_cast<int>(cells.size());
}

TEST(KeypointDistribution, QuadtreeSpreadsWhereStrongestCrowds) {
  const std::vector<cv::KeyPoint> keypoints = Clustered();
  const cv::Rect2f region(0, 0, 640, 480);
  const std::vector<int> quad = DistributeQuadtree(keypoints, region, 300);
  const std::vector<int> best = StrongestKeypoints(keypoints, 300);
  const std::vector<int> grid = DistributeGrid(keypoints, region, 300);
  EXPECT_EQ(quad.size(), 300u);
  EXPECT_EQ(best.size(), 300u);
  EXPECT_EQ(grid.size(), 300u);
  EXPECT_LE(CellsCovered(keypoints, best), 4);   // all in the 100x100 corner
  EXPECT_GE(CellsCovered(keypoints, quad), 40);  // 200 weak points reach nearly all 48 cells
  EXPECT_GE(CellsCovered(keypoints, grid), 40);
  // Strictly increasing, unique indices.
  EXPECT_TRUE(std::is_sorted(quad.begin(), quad.end()));
  EXPECT_EQ(std::set<int>(quad.begin(), quad.end()).size(), quad.size());
}

TEST(KeypointDistribution, QuadtreeKeepsStrongestOfEachNode) {
  // Four well separated pairs: wanting 4 gives one per pair, the stronger one.
  std::vector<cv::KeyPoint> keypoints;
  const cv::Point2f centres[4] = {{50, 50}, {500, 60}, {80, 400}, {600, 430}};
  for (int k = 0; k < 4; ++k) {
    keypoints.emplace_back(centres[k], 7.f, -1.f, 10.f);
    keypoints.emplace_back(centres[k] + cv::Point2f(2, 1), 7.f, -1.f, 20.f + k);
  }
  const std::vector<int> kept = DistributeQuadtree(keypoints, cv::Rect2f(0, 0, 640, 480), 4);
  EXPECT_EQ(kept, (std::vector<int>{1, 3, 5, 7}));
}

TEST(KeypointDistribution, FewerKeypointsThanWantedKeepsAll) {
  std::vector<cv::KeyPoint> keypoints;
  for (int i = 0; i < 10; ++i) keypoints.emplace_back(cv::Point2f(10.f + i, 10.f + i), 7.f);
  keypoints.emplace_back(cv::Point2f(700.f, 10.f), 7.f);  // outside the region: ignored
  EXPECT_EQ(DistributeQuadtree(keypoints, cv::Rect2f(0, 0, 640, 480), 100).size(), 10u);
  EXPECT_TRUE(DistributeQuadtree(keypoints, cv::Rect2f(0, 0, 640, 480), 0).empty());
}

TEST(KeypointDistribution, QuadtreeHandlesWideRegions) {
  // A 3:1 region starts from three root nodes; points in each third survive.
  std::vector<cv::KeyPoint> keypoints;
  for (int i = 0; i < 30; ++i) keypoints.emplace_back(cv::Point2f(5.f + i, 20.f), 7.f, -1.f, 5.f);
  keypoints.emplace_back(cv::Point2f(150.f, 50.f), 7.f, -1.f, 1.f);
  keypoints.emplace_back(cv::Point2f(250.f, 50.f), 7.f, -1.f, 1.f);
  const std::vector<int> kept = DistributeQuadtree(keypoints, cv::Rect2f(0, 0, 300, 100), 3);
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept[1], 30);
  EXPECT_EQ(kept[2], 31);
}

}  // namespace
}  // namespace dynvo
