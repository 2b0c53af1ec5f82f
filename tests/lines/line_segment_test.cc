#include "lines/line_segment.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

namespace dynvo {
namespace {

// The coefficients give signed pixel distances: zero on the segment and its extension,
// +-d at d pixels to either side, whatever the segment's direction and length.
TEST(ImageLineCoefficients, GiveSignedPixelDistances) {
  const LineSegment s{{100.0, 50.0}, {400.0, 450.0}};  // direction (3, 4) / 5
  const Eigen::Vector3d l = ImageLineCoefficients(s);
  EXPECT_NEAR(l.head<2>().norm(), 1.0, 1e-12);
  EXPECT_NEAR(l.dot(s.start.homogeneous()), 0.0, 1e-9);
  EXPECT_NEAR(l.dot(s.end.homogeneous()), 0.0, 1e-9);
  EXPECT_NEAR(l.dot(Eigen::Vector2d(700.0, 850.0).homogeneous()), 0.0, 1e-9);  // on the extension
  const Eigen::Vector2d normal(4.0 / 5.0, -3.0 / 5.0);
  const Eigen::Vector2d mid = 0.5 * (s.start + s.end);
  const double plus = l.dot((mid + 7.0 * normal).homogeneous());
  const double minus = l.dot((mid - 7.0 * normal).homogeneous());
  EXPECT_NEAR(std::abs(plus), 7.0, 1e-9);
  EXPECT_NEAR(plus, -minus, 1e-9);
}

TEST(ImageLineCoefficients, APointHasNoLine) {
  EXPECT_EQ(ImageLineCoefficients({{3.0, 4.0}, {3.0, 4.0}}), Eigen::Vector3d::Zero());
}

}  // namespace
}  // namespace dynvo
