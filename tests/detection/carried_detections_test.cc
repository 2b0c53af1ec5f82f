#include "detection/carried_detections.h"

#include <gtest/gtest.h>

namespace dynvo {
namespace {

TEST(CarriedDetections, CarriesTheLastPeopleByTheMotionWithTheirAge) {
  CarriedDetections carried;
  const Eigen::Matrix3d pan = (Eigen::Matrix3d() << 1, 0, -6, 0, 1, 0, 0, 0, 1).finished();  // 6 px left
  const cv::Size image(640, 480);
  carried.Carry(&pan, image);  // nothing detected yet: nothing to carry
  EXPECT_EQ(carried.age(), -1);
  EXPECT_TRUE(carried.people().empty());
  carried.Detected({{cv::Rect2d(300, 100, 80, 200), 0.9, 0}, {cv::Rect2d(2, 10, 4, 30), 0.5, 0}});
  EXPECT_EQ(carried.age(), 0);
  carried.Carry(&pan, image);
  EXPECT_EQ(carried.age(), 1);
  ASSERT_EQ(carried.people().size(), 1u);  // the second left the image
  EXPECT_NEAR(carried.people()[0].box.x, 294.0, 1e-9);
  EXPECT_NEAR(carried.people()[0].box.width, 80.0, 1e-9);
  carried.Carry(nullptr, image);  // no motion known: the boxes cannot follow
  EXPECT_EQ(carried.age(), 2);
  EXPECT_TRUE(carried.people().empty());
}

}  // namespace
}  // namespace dynvo
