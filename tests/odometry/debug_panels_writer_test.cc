#include "odometry/debug_panels_writer.h"

#include <gtest/gtest.h>

namespace dynvo {
namespace {

// Four 10x10 quadrants of a 20x20 grey frame: masked and moving (top left), masked and static
// (top right), moving and not masked (bottom left), neither (bottom right); a person standing
// still fills the right half of the top-right quadrant.
struct Quadrants {
  cv::Mat bgr = cv::Mat(20, 20, CV_8UC3, cv::Scalar(200, 100, 60));
  cv::Mat mask = cv::Mat::zeros(20, 20, CV_8UC1), moving = mask.clone(), still = mask.clone();
  Quadrants() {
    mask(cv::Rect(0, 0, 20, 10)).setTo(255);
    moving(cv::Rect(0, 0, 10, 20)).setTo(255);
    still(cv::Rect(15, 0, 5, 10)).setTo(255);
  }
};

cv::Vec3b At(const cv::Mat& image, int x, int y) { return image.at<cv::Vec3b>(y, x); }

TEST(DrawMaskAgainstTruth, ColoursEachPixelByHowTheMaskAgreesWithTheTruth) {
  const Quadrants q;
  const cv::Mat out = DrawMaskAgainstTruth(q.bgr, q.mask, q.moving, q.still);
  ASSERT_EQ(out.size(), q.bgr.size());
  ASSERT_EQ(out.type(), CV_8UC3);
  EXPECT_EQ(At(out, 5, 5), cv::Vec3b(0, 255, 0));     // masked, moving
  EXPECT_EQ(At(out, 12, 5), cv::Vec3b(0, 0, 255));    // masked, static
  EXPECT_EQ(At(out, 17, 5), cv::Vec3b(0, 255, 255));  // masked, a person standing still
  EXPECT_EQ(At(out, 5, 15), cv::Vec3b(255, 0, 0));    // moving, missed
  EXPECT_EQ(At(out, 15, 15), cv::Vec3b(100, 50, 30));  // neither: the frame at half brightness
}

TEST(DrawMaskAgainstTruth, WithoutStillPeopleEveryStaticMaskedPixelIsRed) {
  const Quadrants q;
  const cv::Mat out = DrawMaskAgainstTruth(q.bgr, q.mask, q.moving, cv::Mat());
  EXPECT_EQ(At(out, 17, 5), cv::Vec3b(0, 0, 255));
  EXPECT_EQ(At(out, 12, 5), cv::Vec3b(0, 0, 255));
}

}  // namespace
}  // namespace dynvo
