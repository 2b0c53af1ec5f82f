#include "loop/loop_verification.h"

#include <gtest/gtest.h>

#include "loop/box_room_world.h"

namespace dynvo {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// A camera at 1.5 m height in the room looking along the world's yaw direction (z up).
Pose CameraAt(double x, double y, double yaw_deg) {
  const double yaw = yaw_deg * kDeg;
  const Eigen::Vector3d forward(std::cos(yaw), std::sin(yaw), 0.0);
  Eigen::Matrix3d r;
  r.col(2) = forward;
  r.col(0) = forward.cross(Eigen::Vector3d::UnitZ()).normalized();
  r.col(1) = r.col(2).cross(r.col(0));
  Pose pose = Pose::Identity();
  pose.linear() = r;
  pose.translation() = Eigen::Vector3d(x, y, 1.5);
  return pose;
}

// The keyframe a camera at `truth` makes when tracking put it at `tracked`, after `path_m`
// metres and `turned_deg` degrees since the start.
LoopKeyframe Seen(const test::BoxRoom& room, const Pose& truth, const Pose& tracked, double path_m, double turned_deg,
                  uint32_t seed) {
  LoopKeyframe keyframe = MakeLoopKeyframe(0, 0, 0.0, tracked, test::SeeRoom(room, truth, 12, seed),
                                           test::RoomDepth(room, truth), 8, nullptr);
  keyframe.path_m = path_m;
  keyframe.turned_rad = turned_deg * kDeg;
  return keyframe;
}

class LoopVerificationTest : public ::testing::Test {
 protected:
  test::BoxRoom room_ = test::MakeBoxRoom(6000, 2);
};

TEST_F(LoopVerificationTest, ARevisitIsAcceptedWithItsTruePose) {
  const Pose first = CameraAt(0.0, 0.0, 90.0), again = CameraAt(0.2, -0.1, 80.0);
  // Tracking drifted by 6 cm and 2 degrees over the 3 m and 360 degrees between the two.
  const Pose drift = PoseFromAxisAngle({0.0, 2.0 * kDeg, 0.0}, {0.06, 0.0, 0.0});
  const LoopKeyframe candidate = Seen(room_, first, first, 0.0, 0.0, 1);
  const LoopKeyframe query = Seen(room_, again, drift * again, 3.0, 360.0, 2);
  const LoopVerification v = VerifyLoop(query, candidate, room_.camera, {});
  ASSERT_TRUE(v.accepted) << v.reason;
  EXPECT_GT(v.inliers, 100);
  EXPECT_GE(v.cells, 12);
  EXPECT_GT(v.depth_agreement, 0.95);
  const Pose truth = again.inverse() * first;
  EXPECT_LT((v.query_from_candidate.translation() - truth.translation()).norm(), 0.01);
  EXPECT_LT(RotationAngle(Pose(truth.inverse() * v.query_from_candidate)), 0.5 * kDeg);
  EXPECT_GT(v.correction_m, 0.03);
  EXPECT_NEAR(v.correction_deg, 2.0, 0.5);
  // Each inlier match is one room point seen from both.
  ASSERT_EQ(v.inlier_matches.size(), static_cast<size_t>(v.inliers));
  for (const auto& [q, c] : v.inlier_matches)
    EXPECT_LT((truth * candidate.points_in_camera[c] - query.points_in_camera[q]).norm(), 1e-6) << q << " " << c;
}

TEST_F(LoopVerificationTest, ARepeatedTextureElsewhereIsRejectedByTheDrift) {
  // The room turned by 180 degrees is the same room: a camera facing the opposite wall from
  // the opposite side sees exactly what the first one saw (descriptors and depth alike).
  const Pose first = CameraAt(0.5, 0.5, 90.0);
  const Pose half_turn = PoseFromAxisAngle({0.0, 0.0, 180.0 * kDeg}, Eigen::Vector3d::Zero());
  test::BoxRoom mirrored = room_;
  for (Eigen::Vector3d& p : mirrored.points) p = half_turn * p;
  const LoopKeyframe candidate = Seen(room_, first, first, 0.0, 0.0, 1);
  const LoopKeyframe query = Seen(mirrored, half_turn * first, half_turn * first, 3.0, 200.0, 2);
  const LoopVerification v = VerifyLoop(query, candidate, room_.camera, {});
  EXPECT_FALSE(v.accepted);
  EXPECT_EQ(v.reason, "more correction than drift explains");
  EXPECT_GT(v.inliers, 100) << "the impostor passes the pose check";
  EXPECT_GT(v.depth_agreement, 0.95) << "and the depth check";
  EXPECT_GT(v.correction_m, 1.0);
}

TEST_F(LoopVerificationTest, MatchesInOneCornerOrDepthElsewhereAreRejected) {
  const Pose first = CameraAt(0.0, 0.0, 0.0), again = CameraAt(0.1, 0.0, 5.0);
  const LoopKeyframe candidate = Seen(room_, first, first, 0.0, 0.0, 1);
  LoopKeyframe query = Seen(room_, again, again, 3.0, 360.0, 2);
  // Only the features in the top-left quarter keep their descriptors.
  LoopKeyframe corner = query;
  corner.descriptors = query.descriptors.clone();
  for (size_t i = 0; i < corner.pixels.size(); ++i)
    if (corner.pixels[i].x() > 320 || corner.pixels[i].y() > 240) corner.descriptors.row(static_cast<int>(i)) = 0;
  LoopVerification v = VerifyLoop(corner, candidate, room_.camera, {});
  EXPECT_FALSE(v.accepted);
  EXPECT_EQ(v.reason, "inliers in " + std::to_string(v.cells) + " image cells");
  EXPECT_LE(v.cells, 5);
  // The query's depth 40 cm farther than the candidate's points would be.
  query.depth += 0.4;
  v = VerifyLoop(query, candidate, room_.camera, {});
  EXPECT_FALSE(v.accepted);
  EXPECT_EQ(v.reason, "depth does not agree");
  EXPECT_LT(v.depth_agreement, 0.1);
}

}  // namespace
}  // namespace dynvo
