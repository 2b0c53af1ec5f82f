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

}  // namespace
}  // namespace dynvo
