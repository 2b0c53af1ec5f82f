#include "core/pose.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/error.h"

namespace dynvo {
namespace {

TEST(Pose, FromTumNormalisesQuaternion) {
  // (qx,qy,qz,qw) = 2 * (0, 0, sin(45deg), cos(45deg)): 90 degrees about z, not unit length.
  const double s = std::sqrt(0.5);
  const Pose p = PoseFromTum({1, 2, 3}, 0, 0, 2 * s, 2 * s);
  EXPECT_NEAR((p.linear() * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY()).norm(), 0, 1e-12);
  EXPECT_EQ(p.translation(), Eigen::Vector3d(1, 2, 3));
}

TEST(Pose, QuaternionHasNonNegativeW) {
  const Pose p = PoseFromTum({0, 0, 0}, 0.1, 0.2, 0.3, -0.9);
  const Eigen::Quaterniond q = PoseQuaternion(p);
  EXPECT_GE(q.w(), 0.0);
  EXPECT_NEAR(q.norm(), 1.0, 1e-12);
  EXPECT_NEAR((q.toRotationMatrix() - p.linear()).norm(), 0, 1e-12);
}

TEST(Pose, RotationAngleOfAxisAngle) {
  const Pose p = PoseFromAxisAngle({0.3, -0.4, 0.0}, {0, 0, 0});
  EXPECT_NEAR(RotationAngle(p), 0.5, 1e-12);
  EXPECT_NEAR(RotationAngle(Pose::Identity()), 0.0, 1e-12);
}

TEST(Pose, InterpolationGoesFromOneEndToTheOtherAlongTheStep) {
  const Pose a = PoseFromAxisAngle({0.1, 0.2, -0.3}, {1.0, 2.0, 3.0});
  const Pose step = PoseFromAxisAngle({0.0, 0.0, 0.4}, {0.2, -0.1, 0.0});  // 0.4 rad about z
  const Pose b = a * step;
  EXPECT_TRUE(InterpolatePose(a, b, 0.0).isApprox(a, 1e-12));
  EXPECT_TRUE(InterpolatePose(a, b, 1.0).isApprox(b, 1e-12));
  // A quarter of the way: a quarter of the step's angle about its axis, a quarter of its translation.
  const Pose quarter = InterpolatePose(a, b, 0.25);
  const Pose expected = a * PoseFromAxisAngle({0.0, 0.0, 0.1}, {0.05, -0.025, 0.0});
  EXPECT_TRUE(quarter.isApprox(expected, 1e-12));
  EXPECT_NEAR(RotationAngle(Pose(a.inverse() * quarter)), 0.1, 1e-12);
}

TEST(Pose, AngularVelocityIsTheTurnOverTheTimeInTheCamerasFrame) {
  const Pose before = PoseFromAxisAngle({0.3, -0.2, 0.1}, {1.0, 0.0, 2.0});
  const Eigen::Vector3d turn(0.02, -0.05, 0.01);  // radians, in the camera's frame
  const Pose after = before * PoseFromAxisAngle(turn, {0.1, 0.2, 0.0});
  EXPECT_TRUE(AngularVelocity(before, after, 0.5).isApprox(turn / 0.5, 1e-12));
  EXPECT_TRUE(AngularVelocity(before, after, 0.0).isZero(0.0));
  EXPECT_TRUE(AngularVelocity(before, before, 0.5).isZero(1e-15));
}

TEST(Error, FileMessageNamesFileAndLine) {
  EXPECT_EQ(FileMessage("a/rgb.txt", 7, "bad"), "a/rgb.txt:7: bad");
  EXPECT_EQ(FileMessage("a/rgb.txt", 0, "missing"), "a/rgb.txt: missing");
  try {
    ThrowFileError("x.txt", 3, "expected 8 columns");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "x.txt:3: expected 8 columns");
  }
}

}  // namespace
}  // namespace dynvo
