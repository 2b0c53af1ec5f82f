#include "loop/global_bundle_adjustment.h"

#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "loop/box_room_world.h"

namespace dynvo {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// Keyframe k's true pose: on the ring, turned 9 k degrees (neighbours share most of what they see).
Pose TrueKeyframe(int k) { return test::RingPose(9.0 * k); }

// Where a pose graph might leave keyframe k: 0.2 degrees and 3 mm off per keyframe since the first.
Pose Drifted(int k) {
  const Pose step = PoseFromAxisAngle({0.0, 0.2 * kDeg, 0.0}, {0.003, 0.0, 0.0});
  Pose pose = TrueKeyframe(k);
  for (int i = 0; i < k; ++i) pose = pose * step;
  return pose;
}

double PositionError(const Pose& estimate, const Pose& truth) {
  return (estimate.translation() - truth.translation()).norm();
}
double AngleError(const Pose& estimate, const Pose& truth) { return RotationAngle(Pose(truth.inverse() * estimate)); }

class GlobalBundleAdjustmentTest : public ::testing::Test {
 protected:
  // Keyframe k seen from its true pose: features with exact depth; with `tracked`, tracking's
  // observations of the room's points (ids offset by `id_offset`, as a map restarted anew).
  std::shared_ptr<const LoopKeyframe> Keyframe(int k, bool tracked, int64_t id_offset = 0) const {
    LoopKeyframe keyframe = MakeLoopKeyframe(static_cast<size_t>(k), static_cast<size_t>(k), 0.1 * k, Drifted(k),
                                             test::SeeRoom(room_, TrueKeyframe(k), 0, 7), room_depth_, 8, nullptr);
    if (tracked) {
      keyframe.observations = test::ObserveRoom(room_, TrueKeyframe(k));
      for (KeyframeObservation& o : keyframe.observations) o.point_id += id_offset;
    }
    return std::make_shared<const LoopKeyframe>(std::move(keyframe));
  }

  // An accepted loop from keyframe `query` to `candidate` whose inliers are every room point
  // both see (rows of their features, which follow ObserveRoom's order).
  LoopCandidate Loop(int query, int candidate) const {
    LoopCandidate loop;
    loop.keyframe = static_cast<size_t>(query);
    loop.candidate = static_cast<size_t>(candidate);
    loop.verified = loop.verification.accepted = true;
    const std::vector<KeyframeObservation> seen_q = test::ObserveRoom(room_, TrueKeyframe(query));
    const std::vector<KeyframeObservation> seen_c = test::ObserveRoom(room_, TrueKeyframe(candidate));
    for (size_t q = 0; q < seen_q.size(); ++q)
      for (size_t c = 0; c < seen_c.size(); ++c)
        if (seen_c[c].point_id == seen_q[q].point_id)
          loop.verification.inlier_matches.emplace_back(static_cast<int>(q), static_cast<int>(c));
    return loop;
  }

  test::BoxRoom room_ = test::MakeBoxRoom(4000, 3);
  cv::Mat room_depth_ = cv::Mat::zeros(60, 80, CV_32FC1);  // unused by the BA
};

TEST_F(GlobalBundleAdjustmentTest, TrackedPointsPullDriftedKeyframesToTheTruth) {
  std::vector<std::shared_ptr<const LoopKeyframe>> keyframes;
  std::vector<Pose> poses;
  for (int k = 0; k < 8; ++k) {
    keyframes.push_back(Keyframe(k, true));
    poses.push_back(Drifted(k));
  }
  ASSERT_GT(PositionError(poses[7], TrueKeyframe(7)), 0.015);
  const GlobalBundleAdjustmentResult result = RefineKeyframes(keyframes, poses, {}, room_.camera, {}, 1000);
  ASSERT_TRUE(result.report.ok) << result.report.failure;
  EXPECT_EQ(result.report.num_keyframes_fixed, 1);
  EXPECT_EQ(result.report.num_outliers_removed, 0);
  for (int k = 0; k < 8; ++k) {
    EXPECT_LT(PositionError(result.world_from_camera[k], TrueKeyframe(k)), 1e-4) << k;
    EXPECT_LT(AngleError(result.world_from_camera[k], TrueKeyframe(k)), 0.01 * kDeg) << k;
  }
}

TEST_F(GlobalBundleAdjustmentTest, ALoopsInlierMatchesAloneLinkItsKeyframes) {
  // Keyframes 0 and 2 share no tracked point, only a loop's matches; keyframe 1 shares nothing.
  const std::vector<std::shared_ptr<const LoopKeyframe>> keyframes = {Keyframe(0, false), Keyframe(1, false),
                                                                      Keyframe(2, false)};
  const std::vector<Pose> poses = {TrueKeyframe(0), Drifted(1), Drifted(2)};
  const LoopCandidate loop = Loop(2, 0);
  ASSERT_GT(loop.verification.inlier_matches.size(), 50u);
  const GlobalBundleAdjustmentResult result = RefineKeyframes(keyframes, poses, {loop}, room_.camera, {}, 1000);
  ASSERT_TRUE(result.report.ok) << result.report.failure;
  EXPECT_LT(PositionError(result.world_from_camera[2], TrueKeyframe(2)), 1e-4);
  EXPECT_LT(AngleError(result.world_from_camera[2], TrueKeyframe(2)), 0.01 * kDeg);
  EXPECT_TRUE(result.world_from_camera[1].isApprox(poses[1], 0.0)) << "no point links keyframe 1: it stays";
}

TEST_F(GlobalBundleAdjustmentTest, ALoopGivesAtMostItsShareOfPointsSpreadOverItsMatches) {
  const std::vector<std::shared_ptr<const LoopKeyframe>> keyframes = {Keyframe(0, false), Keyframe(1, false)};
  const std::vector<Pose> poses = {TrueKeyframe(0), Drifted(1)};
  const LoopCandidate loop = Loop(1, 0);
  const size_t matches = loop.verification.inlier_matches.size();
  ASSERT_GT(matches, 100u);
  const LocalBaProblem all = MakeGlobalBundleAdjustment(keyframes, poses, {loop}, room_.camera, matches, true);
  EXPECT_EQ(all.points.size(), matches);
  EXPECT_EQ(all.observations.size(), 2 * matches);
  const LocalBaProblem capped = MakeGlobalBundleAdjustment(keyframes, poses, {loop}, room_.camera, 10, true);
  ASSERT_EQ(capped.points.size(), 10u);
  // Spread: the first and the last tenth of the matches both give a point.
  const Eigen::Vector2d first = keyframes[1]->pixels[loop.verification.inlier_matches.front().first];
  EXPECT_TRUE(capped.observations[1].measured.pixel.isApprox(first));
  const size_t last = capped.observations.size() - 1;
  const size_t last_match = (capped.points.size() - 1) * ((matches + 9) / 10);
  EXPECT_TRUE(capped.observations[last].measured.pixel.isApprox(
      keyframes[1]->pixels[loop.verification.inlier_matches[last_match].first]));
  EXPECT_GE(last_match, matches * 8 / 10);
}

TEST_F(GlobalBundleAdjustmentTest, WithoutTheDepthTermTwoKeyframesFixTheScale) {
  std::vector<std::shared_ptr<const LoopKeyframe>> keyframes;
  std::vector<Pose> poses;
  for (int k = 0; k < 8; ++k) {
    keyframes.push_back(Keyframe(k, true));
    poses.push_back(k < 2 ? TrueKeyframe(k) : Drifted(k));
  }
  BundleAdjustmentOptions reprojection_only;
  reprojection_only.virtual_baseline_m = 0.0;
  const GlobalBundleAdjustmentResult result =
      RefineKeyframes(keyframes, poses, {}, room_.camera, reprojection_only, 1000);
  ASSERT_TRUE(result.report.ok) << result.report.failure;
  EXPECT_EQ(result.report.num_keyframes_fixed, 2);
  for (int k = 0; k < 8; ++k) EXPECT_LT(PositionError(result.world_from_camera[k], TrueKeyframe(k)), 1e-4) << k;
  EXPECT_THROW(MakeGlobalBundleAdjustment(keyframes, poses, {}, room_.camera, 0, true), InputError);
}

TEST_F(GlobalBundleAdjustmentTest, ARestartedMapKeepsThePlaceThePoseGraphGaveIt) {
  // Keyframes 0-3 and 4-7 share no point (tracking restarted at 4 with new ids) and no loop.
  std::vector<std::shared_ptr<const LoopKeyframe>> keyframes;
  std::vector<Pose> poses;
  for (int k = 0; k < 8; ++k) {
    keyframes.push_back(Keyframe(k, true, k < 4 ? 0 : 100000));
    poses.push_back(Drifted(k));
  }
  const GlobalBundleAdjustmentResult result = RefineKeyframes(keyframes, poses, {}, room_.camera, {}, 1000);
  ASSERT_TRUE(result.report.ok) << result.report.failure;
  EXPECT_EQ(result.report.num_keyframes_fixed, 2);
  EXPECT_TRUE(result.world_from_camera[4].isApprox(poses[4], 0.0));
  for (int k = 5; k < 8; ++k) {  // the second set agrees with itself, placed by its first keyframe
    const Pose relative = result.world_from_camera[4].inverse() * result.world_from_camera[k];
    const Pose truth = TrueKeyframe(4).inverse() * TrueKeyframe(k);
    EXPECT_LT(PositionError(relative, truth), 1e-4) << k;
    EXPECT_LT(AngleError(relative, truth), 0.01 * kDeg) << k;
  }
  EXPECT_LT(PositionError(result.world_from_camera[3], TrueKeyframe(3)), 1e-4);
}

TEST_F(GlobalBundleAdjustmentTest, WithoutSharedPointsNothingMoves) {
  const std::vector<std::shared_ptr<const LoopKeyframe>> keyframes = {Keyframe(0, false), Keyframe(1, false)};
  const std::vector<Pose> poses = {Drifted(0), Drifted(1)};
  const GlobalBundleAdjustmentResult result = RefineKeyframes(keyframes, poses, {}, room_.camera, {}, 1000);
  EXPECT_FALSE(result.report.ok);
  EXPECT_EQ(result.report.failure, "no point is observed by two keyframes");
  EXPECT_TRUE(result.world_from_camera[1].isApprox(poses[1], 0.0));
}

}  // namespace
}  // namespace dynvo
