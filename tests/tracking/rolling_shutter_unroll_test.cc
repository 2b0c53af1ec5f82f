#include "tracking/rolling_shutter_unroll.h"

#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/Geometry>

namespace dynvo {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kReadout = 0.028;  // Kinect v1, seconds

// A camera turning at `w` (rad/s) about its own axes: stamp_from_camera at tau seconds after
// the stamp.
Eigen::Matrix3d StampFromCameraAt(const Eigen::Vector3d& w, double tau) {
  const Eigen::Vector3d turn = tau * w;
  return turn.isZero() ? Eigen::Matrix3d::Identity() : Eigen::AngleAxisd(turn.norm(), turn.normalized()).matrix();
}

// The feature of a point (in the stamp camera) as a rolling shutter sees it: in the row exposed
// at its own time, found by fixed-point iteration (each step moves the row by far less than it).
void SeeWithRollingShutter(const Camera& camera, const Eigen::Vector3d& w, const Eigen::Vector3d& point,
                           FrameFeatures* f) {
  Eigen::Vector3d seen = point;
  for (int k = 0; k < 20; ++k) {
    const double tau = kReadout * (camera.Project(seen).y() / (camera.height - 1) - 0.5);
    seen = StampFromCameraAt(w, tau).transpose() * point;
  }
  const Eigen::Vector2d pixel = camera.Project(seen);
  f->keypoints.emplace_back(cv::Point2f(static_cast<float>(pixel.x()), static_cast<float>(pixel.y())), 31.0f);
  f->pixels.push_back(pixel);
  f->depths.push_back(seen.z());
  f->points_in_camera.push_back(seen);
}

TEST(RollingShutterUnroll, RowRotationTurnsByTheRowsTimeFromTheStamp) {
  const Camera camera;  // 640 x 480
  const Eigen::Vector3d w(0.0, 60 * kDeg, 0.0);
  EXPECT_TRUE(RowRotation(camera, w, kReadout, (camera.height - 1) / 2.0).isIdentity(1e-15));
  // The top row is exposed half the readout before the stamp, the bottom one half after.
  EXPECT_NEAR(Eigen::AngleAxisd(RowRotation(camera, w, kReadout, 0)).angle(), 60 * kDeg * kReadout / 2, 1e-12);
  EXPECT_TRUE(RowRotation(camera, w, kReadout, 0).isApprox(StampFromCameraAt(w, -kReadout / 2), 1e-12));
  EXPECT_TRUE(RowRotation(camera, w, kReadout, camera.height - 1).isApprox(StampFromCameraAt(w, kReadout / 2), 1e-12));
}

TEST(RollingShutterUnroll, FeaturesMoveToWhereTheCameraAtTheStampSeesThem) {
  const Camera camera;
  const Eigen::Vector3d w = Eigen::Vector3d(0.2, 1.0, 0.1).normalized() * 90 * kDeg;  // a fast hand-held turn
  FrameFeatures f;
  std::vector<Eigen::Vector3d> truth;  // in the stamp camera
  for (double x = -1.2; x <= 1.2; x += 0.3)
    for (double y = -0.9; y <= 0.9; y += 0.3) truth.emplace_back(x, y, 2.0 + 0.5 * x);
  for (const Eigen::Vector3d& p : truth) SeeWithRollingShutter(camera, w, p, &f);
  double largest_shear_px = 0;
  for (size_t i = 0; i < truth.size(); ++i)
    largest_shear_px = std::max(largest_shear_px, (f.pixels[i] - camera.Project(truth[i])).norm());
  EXPECT_GT(largest_shear_px, 8.0);  // 90 deg/s over half of 28 ms: about 11 px at the top and bottom

  const FrameFeatures observed = f;
  UnrollRollingShutter(camera, w, kReadout, &f);
  for (size_t i = 0; i < truth.size(); ++i) {
    EXPECT_LT((f.pixels[i] - camera.Project(truth[i])).norm(), 1e-6) << i;
    EXPECT_LT((f.points_in_camera[i] - truth[i]).norm(), 1e-9) << i;
    EXPECT_NEAR(f.depths[i], truth[i].z(), 1e-9) << i;
    EXPECT_EQ(f.keypoints[i].pt, observed.keypoints[i].pt);  // as detected
  }
}

TEST(RollingShutterUnroll, NoReadoutOrNoTurnChangesNothing) {
  const Camera camera;
  FrameFeatures f;
  SeeWithRollingShutter(camera, Eigen::Vector3d::Zero(), {0.3, -0.8, 2.0}, &f);
  f.depths.push_back(0.0);  // a feature without depth keeps its zero point
  f.pixels.push_back({10.0, 20.0});
  f.points_in_camera.emplace_back(Eigen::Vector3d::Zero());
  f.keypoints.emplace_back(cv::Point2f(10.0f, 20.0f), 31.0f);
  const FrameFeatures before = f;
  UnrollRollingShutter(camera, Eigen::Vector3d(0, 1, 0), 0.0, &f);
  UnrollRollingShutter(camera, Eigen::Vector3d::Zero(), kReadout, &f);
  for (size_t i = 0; i < f.size(); ++i) EXPECT_EQ(f.pixels[i], before.pixels[i]);
  UnrollRollingShutter(camera, Eigen::Vector3d(0, 1, 0), kReadout, &f);
  EXPECT_NE(f.pixels[1], before.pixels[1]);
  EXPECT_EQ(f.depths[1], 0.0);
  EXPECT_TRUE(f.points_in_camera[1].isZero());
}

}  // namespace
}  // namespace dynvo
