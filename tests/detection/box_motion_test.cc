#include "detection/box_motion.h"

#include <gtest/gtest.h>

namespace dynvo {
namespace {

TEST(CarryBox, FollowsAPanAndAZoomAndLosesWhatGoesBehindTheCamera) {
  Eigen::Matrix3d pan = Eigen::Matrix3d::Identity();
  pan(0, 2) = -6.0;  // the image content moves 6 px to the left
  const std::optional<cv::Rect2d> panned = CarryBox(cv::Rect2d(100, 50, 40, 80), pan);
  ASSERT_TRUE(panned);
  EXPECT_NEAR(panned->x, 94.0, 1e-9);
  EXPECT_NEAR(panned->width, 40.0, 1e-9);
  const Eigen::Matrix3d zoom = Eigen::Vector3d(2.0, 2.0, 1.0).asDiagonal();
  const std::optional<cv::Rect2d> zoomed = CarryBox(cv::Rect2d(100, 50, 40, 80), zoom);
  ASSERT_TRUE(zoomed);
  EXPECT_NEAR(zoomed->x, 200.0, 1e-9);
  EXPECT_NEAR(zoomed->height, 160.0, 1e-9);
  Eigen::Matrix3d behind = Eigen::Matrix3d::Identity();
  behind(2, 0) = -0.01;  // w < 0 for x > 100
  EXPECT_FALSE(CarryBox(cv::Rect2d(100, 50, 40, 80), behind));
}

}  // namespace
}  // namespace dynvo
