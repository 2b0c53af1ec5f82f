#include "tracking/static_verification.h"

#include <random>

#include <gtest/gtest.h>

#include "core/error.h"
#include "synthetic_world.h"

namespace dynvo {
namespace {

// The world's points seen from `camera_from_world` with exact descriptors, the first `moved`
// of them shifted right by `shift_px` in the image (as if they had moved since they were mapped).
FrameFeatures SeenFeatures(const test::SyntheticWorld& world, const Pose& camera_from_world, int moved, double shift_px,
                           std::vector<int>* point_of_feature) {
  FrameFeatures f;
  std::vector<int> rows;
  for (int i = 0; i < static_cast<int>(world.points.size()); ++i) {
    const Eigen::Vector3d p = camera_from_world * world.points[static_cast<size_t>(i)];
    Eigen::Vector2d px = world.camera.Project(p);
    if (!world.camera.InImage(px, 10.0)) continue;
    if (static_cast<int>(rows.size()) < moved) px.x() += shift_px;
    rows.push_back(i);
    f.keypoints.emplace_back(cv::Point2f(static_cast<float>(px.x()), static_cast<float>(px.y())), 31.0f,
                             world.angles_deg[static_cast<size_t>(i)]);
    f.pixels.push_back(px);
    f.depths.push_back(p.z());
    f.points_in_camera.push_back(p);
  }
  f.descriptors.create(static_cast<int>(rows.size()), 32, CV_8UC1);
  for (size_t k = 0; k < rows.size(); ++k)
    world.descriptors.row(rows[k]).copyTo(f.descriptors.row(static_cast<int>(k)));
  *point_of_feature = rows;
  return f;
}

class VerifyStaticFeaturesTest : public ::testing::Test {
 protected:
  test::SyntheticWorld world_ = test::MakeWorld(300, {-2.0, -1.5, 2.5}, {2.0, 1.5, 5.0}, 3);
  Pose pose_ = PoseFromAxisAngle({0.02, -0.05, 0.01}, {0.1, 0.0, -0.05});
  std::vector<uint8_t> none_taken_ = std::vector<uint8_t>(300, 0);
};

TEST_F(VerifyStaticFeaturesTest, AcceptsFeaturesWhereTheMapPutsThemAndRejectsMovedOnes) {
  // 40 features moved 6 px: twice the 3 px bar; the others sit exactly on their projection.
  std::vector<int> point_of;
  const FrameFeatures masked = SeenFeatures(world_, pose_, 40, 6.0, &point_of);
  ASSERT_GT(masked.size(), 150u);
  const std::vector<Match> verified =
      VerifyStaticFeatures(world_.points, world_.descriptors, &world_.angles_deg, masked, world_.camera, pose_,
                           MatchOptions{}, 3.0, none_taken_);
  int moved = 0, right_point = 0;
  for (const Match& m : verified) {
    moved += m.feature_index < 40 ? 1 : 0;
    right_point += m.point_index == point_of[static_cast<size_t>(m.feature_index)] ? 1 : 0;
  }
  EXPECT_EQ(moved, 0);
  EXPECT_EQ(right_point, static_cast<int>(verified.size()));
  // Every unmoved feature matches its own point (exact descriptor, zero error).
  EXPECT_EQ(static_cast<int>(verified.size()), static_cast<int>(masked.size()) - 40);
}

TEST_F(VerifyStaticFeaturesTest, SkipsTakenPointsAndIsOffAtZero) {
  std::vector<int> point_of;
  const FrameFeatures masked = SeenFeatures(world_, pose_, 0, 0.0, &point_of);
  std::vector<uint8_t> taken = none_taken_;
  for (size_t k = 0; k < 10; ++k) taken[static_cast<size_t>(point_of[k])] = 1;
  const std::vector<Match> verified = VerifyStaticFeatures(world_.points, world_.descriptors, &world_.angles_deg,
                                                           masked, world_.camera, pose_, MatchOptions{}, 3.0, taken);
  EXPECT_EQ(static_cast<int>(verified.size()), static_cast<int>(masked.size()) - 10);
  for (const Match& m : verified) EXPECT_FALSE(taken[static_cast<size_t>(m.point_index)]);
  EXPECT_TRUE(VerifyStaticFeatures(world_.points, world_.descriptors, &world_.angles_deg, masked, world_.camera, pose_,
                                   MatchOptions{}, 0.0, none_taken_)
                  .empty());
  EXPECT_THROW(VerifyStaticFeatures(world_.points, world_.descriptors, &world_.angles_deg, masked, world_.camera, pose_,
                                    MatchOptions{}, 3.0, std::vector<uint8_t>(5, 0)),
               InputError);
}

}  // namespace
}  // namespace dynvo
