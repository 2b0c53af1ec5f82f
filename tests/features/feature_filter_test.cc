#include "features/feature_filter.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace dynvo {
namespace {

// Ten features on a diagonal, each descriptor filled with its index.
FrameFeatures Diagonal() {
  FrameFeatures f;
  f.descriptors = cv::Mat(10, 32, CV_8UC1);
  for (int i = 0; i < 10; ++i) {
    const float x = 20.f + 40.f * i, y = 10.f + 30.f * i;
    f.keypoints.emplace_back(cv::Point2f(x, y), 31.f, 10.f * i, 1.f, i % 3);
    f.descriptors.row(i).setTo(i);
    f.pixels.emplace_back(x + 0.5, y - 0.5);
    f.depths.push_back(i % 2 ? 1.0 + i : 0.0);
    f.points_in_camera.emplace_back(i, 0, f.depths.back());
  }
  return f;
}

TEST(FeatureFilter, FeaturesInsideTheMaskRemoved) {
  const FrameFeatures f = Diagonal();
  cv::Mat mask(480, 640, CV_8UC1, cv::Scalar(0));
  mask(cv::Rect(90, 60, 120, 100)).setTo(1);  // covers features 2, 3, 4 (x 100..180)
  const FeatureSplit split = SplitByMask(f, mask);
  ASSERT_EQ(split.removed.size(), 3u);
  ASSERT_EQ(split.kept.size(), 7u);
  const int removed[3] = {2, 3, 4}, kept[7] = {0, 1, 5, 6, 7, 8, 9};
  EXPECT_EQ(split.removed_indices, std::vector<int>(removed, removed + 3));
  EXPECT_EQ(split.kept_indices, std::vector<int>(kept, kept + 7));
  for (int k = 0; k < 3; ++k) {
    const int i = removed[k];
    EXPECT_EQ(split.removed.keypoints[k].pt, f.keypoints[i].pt);
    EXPECT_EQ(split.removed.descriptors.at<uint8_t>(k, 31), i);
    EXPECT_EQ(split.removed.pixels[k], f.pixels[i]);
    EXPECT_EQ(split.removed.depths[k], f.depths[i]);
    EXPECT_EQ(split.removed.points_in_camera[k], f.points_in_camera[i]);
  }
  for (int k = 0; k < 7; ++k) {
    const int i = kept[k];
    EXPECT_EQ(split.kept.keypoints[k].octave, f.keypoints[i].octave);
    EXPECT_EQ(split.kept.descriptors.at<uint8_t>(k, 0), i);
    EXPECT_EQ(split.kept.depths[k], f.depths[i]);
  }
}

TEST(FeatureFilter, EmptyMaskKeepsAllAndBadMaskThrows) {
  const FrameFeatures f = Diagonal();
  const FeatureSplit split = SplitByMask(f, cv::Mat());
  EXPECT_EQ(split.kept.size(), 10u);
  EXPECT_EQ(split.removed.size(), 0u);
  EXPECT_EQ(split.removed.descriptors.cols, 32);
  EXPECT_THROW(SplitByMask(f, cv::Mat(480, 640, CV_32FC1)), InputError);
  // A mask smaller than the image: features beyond it are kept.
  const FeatureSplit small = SplitByMask(f, cv::Mat(100, 100, CV_8UC1, cv::Scalar(255)));
  EXPECT_EQ(small.removed.size(), 2u);  // (20,10) and (60,40)
}

TEST(FeatureFilter, SelectFeaturesFollowsIndices) {
  const FrameFeatures f = Diagonal();
  const FrameFeatures s = SelectFeatures(f, {7, 2});
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s.descriptors.at<uint8_t>(0, 5), 7);
  EXPECT_EQ(s.descriptors.at<uint8_t>(1, 5), 2);
  EXPECT_THROW(SelectFeatures(f, {10}), InputError);
}

TEST(FeatureFilter, AppendFeaturesRestoresASplit) {
  const FrameFeatures f = Diagonal();
  cv::Mat mask(480, 640, CV_8UC1, cv::Scalar(0));
  mask(cv::Rect(0, 0, 180, 480)).setTo(1);  // features 0..3 (x 20..140)
  const FeatureSplit split = SplitByMask(f, mask);
  FrameFeatures joined = split.removed;
  AppendFeatures(split.kept, &joined);
  ASSERT_EQ(joined.size(), f.size());
  ASSERT_EQ(joined.descriptors.rows, 10);
  for (int i = 0; i < 10; ++i) {  // removed 0..3 came first, kept 4..9 after: the same order
    EXPECT_EQ(joined.keypoints[i].pt, f.keypoints[i].pt);
    EXPECT_EQ(joined.descriptors.at<uint8_t>(i, 0), i);
    EXPECT_EQ(joined.pixels[i], f.pixels[i]);
    EXPECT_EQ(joined.depths[i], f.depths[i]);
    EXPECT_EQ(joined.points_in_camera[i], f.points_in_camera[i]);
  }
  FrameFeatures empty;
  AppendFeatures(f, &empty);
  EXPECT_EQ(empty.size(), 10u);
  EXPECT_EQ(empty.descriptors.rows, 10);
  FrameFeatures wide = f;
  wide.descriptors = cv::Mat(10, 64, CV_8UC1, cv::Scalar(0));
  EXPECT_THROW(AppendFeatures(f, &wide), InputError);
}

}  // namespace
}  // namespace dynvo
