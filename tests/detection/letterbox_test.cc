#include "detection/letterbox.h"

#include <gtest/gtest.h>

namespace dynvo {
namespace {

// 640 x 480 in 320 x 320: half size, 40 rows of grey above and below.
TEST(Letterbox, KeepsTheAspectAndCentresTheImage) {
  const Letterbox fit = FitLetterbox(cv::Size(640, 480), 320);
  EXPECT_DOUBLE_EQ(fit.scale, 0.5);
  EXPECT_DOUBLE_EQ(fit.left, 0.0);
  EXPECT_DOUBLE_EQ(fit.top, 40.0);
  const cv::Rect2d box = fit.ToImage(cv::Rect2d(100, 60, 50, 200));
  EXPECT_DOUBLE_EQ(box.x, 200.0);
  EXPECT_DOUBLE_EQ(box.y, 40.0);  // (60 - 40) x 2
  EXPECT_DOUBLE_EQ(box.width, 100.0);
  EXPECT_DOUBLE_EQ(box.height, 400.0);
  const Letterbox tall = FitLetterbox(cv::Size(240, 480), 320);  // portrait: grey at the sides
  EXPECT_DOUBLE_EQ(tall.left, 80.0);  // 240 x 480 at 2/3: 160 wide
  EXPECT_DOUBLE_EQ(tall.top, 0.0);
}

// A white image with one black square: in the input, grey outside the image and the square
// where the letterbox says it is.
TEST(Letterbox, PlacesThePixelsWhereTheBoxesMapBack) {
  cv::Mat image(480, 640, CV_8UC3, cv::Scalar::all(255));
  image(cv::Rect(200, 100, 80, 80)).setTo(cv::Scalar::all(0));
  const Letterbox fit = FitLetterbox(image.size(), 320);
  const cv::Mat input = LetterboxImage(image, fit, 320);
  ASSERT_EQ(input.size(), cv::Size(320, 320));
  ASSERT_EQ(input.type(), CV_8UC3);
  EXPECT_EQ(input.at<cv::Vec3b>(10, 160), cv::Vec3b(114, 114, 114));   // above the image
  EXPECT_EQ(input.at<cv::Vec3b>(310, 160), cv::Vec3b(114, 114, 114));  // below it
  EXPECT_EQ(input.at<cv::Vec3b>(45, 10), cv::Vec3b(255, 255, 255));    // the image's first rows
  const cv::Rect2d square = fit.ToImage(cv::Rect2d(100, 90, 40, 40));  // where the square lands
  EXPECT_NEAR(square.x, 200.0, 1e-9);
  EXPECT_NEAR(square.y, 100.0, 1e-9);
  EXPECT_EQ(input.at<cv::Vec3b>(110, 120), cv::Vec3b(0, 0, 0));
  EXPECT_EQ(input.at<cv::Vec3b>(110, 95), cv::Vec3b(255, 255, 255));
}

}  // namespace
}  // namespace dynvo
