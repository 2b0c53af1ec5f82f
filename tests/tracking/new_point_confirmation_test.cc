#include "tracking/new_point_confirmation.h"

#include <random>

#include <gtest/gtest.h>

#include "core/error.h"

namespace dynvo {
namespace {

// The situation of a frame just after a keyframe (the truth is known): a trusted background on a
// wall about 4 m away, a person 1.7 m away whose points the keyframe made (unconfirmed) and who
// has since moved sideways by `person_shift_px` in the image, and unconfirmed points the keyframe
// made on the wall (static). Pixels carry 0.3 px of noise.
class ConfirmNewPointsTest : public ::testing::Test {
 protected:
  void Build(double person_shift_px) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::normal_distribution<double> noise(0.0, 0.3);
    points_.clear();
    pixels_.clear();
    unconfirmed_.clear();
    const Pose world_from_camera = truth_.inverse();
    auto add = [&](const Eigen::Vector3d& in_camera, bool unconfirmed, double shift_px) {
      points_.push_back(world_from_camera * in_camera);
      Eigen::Vector2d px = camera_.Project(in_camera);
      px += Eigen::Vector2d(noise(rng) + shift_px, noise(rng));
      pixels_.push_back(px);
      unconfirmed_.push_back(unconfirmed ? 1 : 0);
    };
    for (int i = 0; i < 300; ++i)  // trusted wall
      add({2.3 * u(rng), 1.7 * u(rng), 4.0 + 0.1 * u(rng)}, false, 0.0);
    for (int i = 0; i < 40; ++i)  // new points on the wall: static
      add({2.3 * u(rng), 1.7 * u(rng), 4.0 + 0.1 * u(rng)}, true, 0.0);
    for (int i = 0; i < 60; ++i)  // new points on the person: moved
      add({0.5 + 0.25 * u(rng), 0.2 + 0.6 * u(rng), 1.7 + 0.1 * u(rng)}, true, person_shift_px);
    full_ = RefinePose(points_, pixels_, camera_, truth_, options_);
    ASSERT_TRUE(full_.ok);
  }
  double CentreError(const Pose& camera_from_world) const {
    return (camera_from_world.inverse().translation() - truth_.inverse().translation()).norm();
  }

  Camera camera_;
  PoseSolverOptions options_;
  Pose truth_ = PoseFromAxisAngle({0.03, -0.02, 0.01}, {0.05, -0.02, 0.1});
  std::vector<Eigen::Vector3d> points_;
  std::vector<Eigen::Vector2d> pixels_;
  std::vector<uint8_t> unconfirmed_;
  PoseEstimate full_;
};

TEST_F(ConfirmNewPointsTest, RejectsNewPointsThatMovedAndRecoversThePose) {
  Build(9.0);
  // The premise: the moved person pulls the pose refined from everything, and some of its
  // points pass as inliers there.
  const double pulled = CentreError(full_.camera_from_world);
  ASSERT_GT(pulled, 0.006);
  int person_inliers = 0;
  for (size_t i = 340; i < 400; ++i) person_inliers += full_.inliers[i];
  ASSERT_GT(person_inliers, 10);

  const NewPointConfirmation checked =
      ConfirmNewPoints(points_, pixels_, unconfirmed_, full_, camera_, options_, 0.003);
  ASSERT_TRUE(checked.estimate.ok);
  EXPECT_GT(checked.shift_m, 0.003);
  EXPECT_LT(CentreError(checked.estimate.camera_from_world), pulled / 4);
  int person_confirmed = 0, person_kept = 0, wall_confirmed = 0;
  for (size_t i = 0; i < 400; ++i) {
    if (i >= 300 && i < 340) wall_confirmed += checked.confirmed[i];
    if (i >= 340) {
      person_confirmed += checked.confirmed[i];
      person_kept += checked.estimate.inliers[i];
    }
    if (i < 300) {
      EXPECT_FALSE(checked.confirmed[i]) << "trusted points are not confirmed again";
    }
  }
  EXPECT_EQ(person_confirmed, 0);
  EXPECT_EQ(person_kept, 0);
  // Every person inlier is rejected, and at most a couple of static new points on the tails of
  // the 0.3 px noise against the bar of min(3 px, 2 x RMS).
  EXPECT_GE(checked.rejected, person_inliers);
  EXPECT_LE(checked.rejected, person_inliers + 2);
  EXPECT_GE(wall_confirmed, 38);
}

TEST_F(ConfirmNewPointsTest, KeepsTheEstimateWhenTheNewPointsAgree) {
  Build(0.0);
  const NewPointConfirmation checked =
      ConfirmNewPoints(points_, pixels_, unconfirmed_, full_, camera_, options_, 0.003);
  EXPECT_LT(checked.shift_m, 0.003);
  EXPECT_TRUE(checked.estimate.camera_from_world.isApprox(full_.camera_from_world));
  EXPECT_EQ(checked.estimate.inliers, full_.inliers);
  EXPECT_EQ(checked.rejected, 0);
  for (size_t i = 0; i < 400; ++i) EXPECT_EQ(checked.confirmed[i], unconfirmed_[i] && full_.inliers[i]) << i;
}

TEST_F(ConfirmNewPointsTest, ALargerShiftBarTrustsTheEstimate) {
  Build(9.0);
  const NewPointConfirmation checked = ConfirmNewPoints(points_, pixels_, unconfirmed_, full_, camera_, options_, 1.0);
  EXPECT_TRUE(checked.estimate.camera_from_world.isApprox(full_.camera_from_world));
  EXPECT_EQ(checked.rejected, 0);
}

TEST_F(ConfirmNewPointsTest, TooFewTrustedPointsLeaveTheEstimateStanding) {
  Build(0.0);
  std::vector<uint8_t> all_new(unconfirmed_.size(), 1);
  for (size_t i = 0; i < 5; ++i) all_new[i] = 0;  // fewer than pose.min_inliers trusted
  const NewPointConfirmation checked = ConfirmNewPoints(points_, pixels_, all_new, full_, camera_, options_, 0.003);
  EXPECT_TRUE(checked.estimate.camera_from_world.isApprox(full_.camera_from_world));
  EXPECT_EQ(checked.shift_m, 0.0);
  for (size_t i = 5; i < 400; ++i) EXPECT_EQ(checked.confirmed[i], full_.inliers[i]) << i;
}

TEST_F(ConfirmNewPointsTest, WithNothingUnconfirmedReturnsTheEstimateAndChecksSizes) {
  Build(0.0);
  const std::vector<uint8_t> none(unconfirmed_.size(), 0);
  const NewPointConfirmation checked = ConfirmNewPoints(points_, pixels_, none, full_, camera_, options_, 0.003);
  EXPECT_TRUE(checked.estimate.camera_from_world.isApprox(full_.camera_from_world));
  EXPECT_EQ(checked.confirmed, none);
  EXPECT_THROW(ConfirmNewPoints(points_, pixels_, std::vector<uint8_t>(3, 1), full_, camera_, options_, 0.003),
               InputError);
}

}  // namespace
}  // namespace dynvo
