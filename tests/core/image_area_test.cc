#include "core/image_area.h"

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "core/error.h"

namespace dynvo {
namespace {

int PixelsOutside(const cv::Mat& filled, const cv::Mat& valid) {
  cv::Mat outside;
  cv::bitwise_and(filled, valid == 0, outside);
  return cv::countNonZero(outside);
}

TEST(ConvexAreaInside, FullMaskIsTheWholeImage) {
  EXPECT_TRUE(ConvexAreaInside(cv::Mat(48, 64, CV_8UC1, cv::Scalar(255))).empty());
  EXPECT_THROW(ConvexAreaInside(cv::Mat::zeros(48, 64, CV_8UC1)), InputError);
  EXPECT_THROW(ConvexAreaInside(cv::Mat(48, 64, CV_32FC1)), InputError);
}

TEST(ConvexAreaInside, EllipseIsCoveredWithinItsEdgeAndNothingOutside) {
  // An ellipse is convex: the polygon fills it up to about a pixel along its edge.
  cv::Mat valid = cv::Mat::zeros(480, 640, CV_8UC1);
  cv::ellipse(valid, cv::Point(320, 240), cv::Size(300, 220), 0, 0, 360, cv::Scalar(255), cv::FILLED);
  const ImageArea area = ConvexAreaInside(valid);
  ASSERT_GE(area.size(), 3u);
  const cv::Mat filled = AreaMask(area, valid.size());
  EXPECT_EQ(PixelsOutside(filled, valid), 0);
  const double perimeter = CV_PI * (300 + 220) * 1.1;
  EXPECT_GT(cv::countNonZero(filled), cv::countNonZero(valid) - 2.0 * perimeter);
}

TEST(ConvexAreaInside, NonConvexRegionShrinksUntilInside) {
  // An L shape: its hull covers the missing quadrant, so the polygon must shrink into the L
  // (to a small part of it: the method is meant for convex regions).
  cv::Mat valid = cv::Mat::zeros(200, 200, CV_8UC1);
  valid(cv::Rect(0, 0, 200, 100)).setTo(255);
  valid(cv::Rect(0, 0, 100, 200)).setTo(255);
  const ImageArea area = ConvexAreaInside(valid);
  const cv::Mat filled = AreaMask(area, valid.size());
  EXPECT_EQ(PixelsOutside(filled, valid), 0);
  EXPECT_GT(cv::countNonZero(filled), 0);
}

TEST(ScaleArea, ScalesVerticesAndKeepsEmpty) {
  EXPECT_TRUE(ScaleArea({}, 0.5).empty());
  const ImageArea scaled = ScaleArea({{10, 20}, {30, 40}, {10, 40}}, 0.5);
  ASSERT_EQ(scaled.size(), 3u);
  EXPECT_EQ(scaled[1], cv::Point2f(15, 20));
}

TEST(AreaMask, EmptyAreaIsAllImage) {
  EXPECT_EQ(cv::countNonZero(AreaMask({}, cv::Size(8, 6))), 48);
  // The square with corners (2, 1) and (5, 4) covers 4 x 4 pixels.
  EXPECT_EQ(cv::countNonZero(AreaMask({{2, 1}, {5, 1}, {5, 4}, {2, 4}}, cv::Size(8, 6))), 16);
}

}  // namespace
}  // namespace dynvo
