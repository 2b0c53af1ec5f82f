#include "odometry/mask_quality.h"

#include <gtest/gtest.h>

namespace dynvo {
namespace {

TEST(MaskQuality, CountsKnownOverlap) {
  cv::Mat truth = cv::Mat::zeros(10, 10, CV_8UC1), detected = cv::Mat::zeros(10, 10, CV_8UC1);
  truth(cv::Rect(0, 0, 4, 5)).setTo(255);     // 20 pixels
  detected(cv::Rect(2, 0, 4, 5)).setTo(255);  // 20 pixels, 10 shared
  const MaskCounts c = CompareMasks(detected, truth);
  EXPECT_EQ(c.true_positive, 10);
  EXPECT_EQ(c.false_positive, 10);
  EXPECT_EQ(c.false_negative, 10);
  EXPECT_DOUBLE_EQ(c.Precision(), 0.5);
  EXPECT_DOUBLE_EQ(c.Recall(), 0.5);
  EXPECT_DOUBLE_EQ(c.Iou(), 10.0 / 30.0);
}

TEST(MaskQuality, EmptyCasesAreDefined) {
  cv::Mat truth = cv::Mat::zeros(4, 4, CV_8UC1);
  MaskCounts none = CompareMasks(cv::Mat(), truth);
  EXPECT_DOUBLE_EQ(none.Iou(), 1.0);
  truth.at<uchar>(1, 1) = 255;
  MaskCounts missed = CompareMasks(cv::Mat(), truth);
  EXPECT_EQ(missed.false_negative, 1);
  EXPECT_DOUBLE_EQ(missed.Recall(), 0.0);
  EXPECT_DOUBLE_EQ(missed.Precision(), 1.0);
  MaskCounts sum;
  sum += missed;
  sum += missed;
  EXPECT_EQ(sum.false_negative, 2);
}

FrameFeatures At(const std::vector<cv::Point2f>& points) {
  FrameFeatures f;
  for (const cv::Point2f& p : points) f.keypoints.emplace_back(p, 7.0f);
  return f;
}

TEST(StillFeatureCounts, CountsTheFeaturesOnStillPeopleKeptAndRemoved) {
  cv::Mat still = cv::Mat::zeros(20, 20, CV_8UC1);
  still(cv::Rect(0, 0, 10, 20)).setTo(255);  // the left half is a person sitting still
  FeatureSplit split;
  split.kept = At({{2, 3}, {4.4f, 15}, {15, 5}, {25, 5}});  // two on them, one off, one outside the image
  split.removed = At({{9.6f, 2}, {1, 1}, {12, 12}});        // 9.6 rounds to 10: off them
  const StillFeatureCounts c = CountStillFeatures(split, still);
  EXPECT_EQ(c.detected, 3);
  EXPECT_EQ(c.kept, 2);
  EXPECT_DOUBLE_EQ(c.KeptShare(), 2.0 / 3.0);
  StillFeatureCounts sum;
  EXPECT_DOUBLE_EQ(sum.KeptShare(), 1.0);  // nobody still: nothing lost
  sum += c;
  sum += c;
  EXPECT_EQ(sum.detected, 6);
  EXPECT_EQ(sum.kept, 4);
}

}  // namespace
}  // namespace dynvo
