#include "core/rolling_shutter.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

namespace dynvo {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

Camera KinectLike() {
  Camera camera;
  camera.rolling_shutter_readout_s = 0.028;
  return camera;
}

TEST(RollingShutter, RowOffsetsSpanTheReadoutWithTheMiddleRowAtTheStamp) {
  EXPECT_DOUBLE_EQ(RowExposureOffset(0, 481, 0.028), -0.014);
  EXPECT_DOUBLE_EQ(RowExposureOffset(240, 481, 0.028), 0.0);
  EXPECT_DOUBLE_EQ(RowExposureOffset(480, 481, 0.028), 0.014);
  EXPECT_DOUBLE_EQ(RowExposureOffset(120, 481, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(RowExposureOffset(0, 1, 0.028), 0.0);
}

TEST(RollingShutter, TheBottomRowsCameraHasTurnedOnByHalfTheReadout) {
  const Camera camera = KinectLike();
  const Eigen::Vector3d turn(0.0, 60.0 * kDeg, 0.0);  // a pan at 60 deg/s
  const Eigen::Matrix3d bottom = StampFromRow(camera, turn, camera.height - 1);
  const Eigen::AngleAxisd angle_axis(bottom);
  EXPECT_NEAR(angle_axis.angle(), 60.0 * kDeg * 0.014, 1e-12);
  EXPECT_NEAR(angle_axis.axis().y(), 1.0, 1e-12);
  EXPECT_TRUE(StampFromRow(camera, turn, 0).isApprox(bottom.transpose(), 1e-12));
  EXPECT_TRUE(StampFromRow(camera, turn, (camera.height - 1) / 2.0).isIdentity(1e-15));
  // A global shutter or no turn: every row is the stamp's camera.
  EXPECT_TRUE(StampFromRow(Camera(), turn, 0).isIdentity(0.0));
  EXPECT_TRUE(StampFromRow(camera, Eigen::Vector3d::Zero(), 0).isIdentity(0.0));
}

TEST(RollingShutter, APointSeenFromItsRowComesBackToWhereTheStampsCameraSeesIt) {
  const Camera camera = KinectLike();
  const Eigen::Vector3d turn(0.2, -0.9, 0.1);  // rad/s
  const Eigen::Vector3d point(0.4, 0.7, 2.0);  // in the stamp's camera: low in the image
  // The row that sees the point, and how it sees it: by fixed point on the row.
  Eigen::Vector3d from_row = point;
  for (int i = 0; i < 20; ++i) from_row = StampFromRow(camera, turn, camera.Project(from_row).y()).transpose() * point;
  const Eigen::Vector2d seen = camera.Project(from_row);
  EXPECT_GT((seen - camera.Project(point)).norm(), 1.0);  // the shutter moved it
  const Eigen::Vector3d back = StampFromRow(camera, turn, seen.y()) * from_row;
  EXPECT_LT((back - point).norm(), 1e-12);
}

}  // namespace
}  // namespace dynvo
