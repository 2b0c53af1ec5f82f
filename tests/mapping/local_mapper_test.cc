#include "mapping/local_mapper.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/executor.h"
#include "keyframe_scene.h"

namespace dynvo {
namespace {

using test::BuildScene;
using test::Scene;
using test::TranslationError;

// Local BA options whose results join the map `frames` after the BA began (0 = at once).
BundleAdjustmentOptions MergedAfter(int frames) {
  BundleAdjustmentOptions options;
  options.merge_delay_frames = frames;
  return options;
}

TEST(LocalMapper, RejectsInvalidOptions) {
  BundleAdjustmentOptions options;
  options.window_keyframes = 0;
  EXPECT_THROW(LocalMapper(Camera{}, options), InputError);
}

// Solved inline (merge_delay_frames 0): the newest keyframe, 3 cm off its true pose, comes back
// to it; the mapper hands its pose on.
TEST(LocalMapper, AdjustsTheNewestKeyframeOfATrackedFrame) {
  Scene s;
  BuildScene(s, 5, 0.0, 4);
  const size_t newest = s.map.num_keyframes() - 1;
  s.map.SetKeyframePose(newest, PoseFromAxisAngle({0, 0, 0}, {0.03, 0, 0}) * s.true_camera_from_world[newest]);
  LocalMapper mapper(s.camera, MergedAfter(0));
  const MappingPacket packet = mapper.Process(42, true, s.map);
  ASSERT_EQ(packet.status, MappingStatus::kAdjusted) << packet.failure;
  EXPECT_EQ(packet.frame, 42u);
  // Noise-free observations: the truth is the optimum (bar: 0.3% of the perturbation).
  EXPECT_LT(TranslationError(s.map.keyframes()[newest].camera_from_world, s.true_camera_from_world[newest]), 1e-4);
  EXPECT_TRUE(packet.keyframe_world_from_camera.isApprox(s.map.keyframes()[newest].camera_from_world.inverse()));
  EXPECT_LT(packet.rms_px, 0.01);
}

TEST(LocalMapper, LeavesTheMapAloneWithoutAKeyframeOrWhenOff) {
  Scene s;
  BuildScene(s, 5, 0.0, 4);
  const Pose off = PoseFromAxisAngle({0, 0, 0}, {0.03, 0, 0}) * s.true_camera_from_world[4];
  s.map.SetKeyframePose(4, off);
  EXPECT_EQ(LocalMapper(s.camera, {}).Process(1, false, s.map).status, MappingStatus::kIdle);
  BundleAdjustmentOptions disabled;
  disabled.enabled = false;
  EXPECT_EQ(LocalMapper(s.camera, disabled).Process(1, true, s.map).status, MappingStatus::kOff);
  EXPECT_TRUE(s.map.keyframes()[4].camera_from_world.isApprox(off, 1e-15));
}

// A BA beside tracking (merge_delay_frames 2, one worker) leaves the map alone until two frames
// later, then gives exactly what the BA between frames gives: the result never depends on timing.
TEST(LocalMapper, MergesABaBesideTrackingAFixedNumberOfFramesLater) {
  Scene inline_scene, beside_scene;
  BuildScene(inline_scene, 5, 0.5, 4);
  BuildScene(beside_scene, 5, 0.5, 4);
  const Pose off = PoseFromAxisAngle({0, 0, 0}, {0.03, 0, 0}) * inline_scene.true_camera_from_world[4];
  inline_scene.map.SetKeyframePose(4, off);
  beside_scene.map.SetKeyframePose(4, off);
  const MappingPacket at_once = LocalMapper(inline_scene.camera, MergedAfter(0)).Process(10, true, inline_scene.map);
  ASSERT_EQ(at_once.status, MappingStatus::kAdjusted) << at_once.failure;

  Executor executor(1);
  LocalMapper mapper(beside_scene.camera, MergedAfter(2), &executor);
  MappingPacket packet = mapper.Process(10, true, beside_scene.map);
  EXPECT_TRUE(packet.started);
  EXPECT_EQ(packet.status, MappingStatus::kIdle);
  EXPECT_EQ(mapper.Process(11, false, beside_scene.map).status, MappingStatus::kIdle);
  EXPECT_TRUE(beside_scene.map.keyframes()[4].camera_from_world.isApprox(off, 1e-15));
  packet = mapper.Process(12, false, beside_scene.map);
  ASSERT_EQ(packet.status, MappingStatus::kAdjusted) << packet.failure;
  EXPECT_FALSE(packet.started);
  EXPECT_EQ(packet.keyframe_frame, 10u);
  for (size_t k = 0; k < 5; ++k)
    EXPECT_EQ(beside_scene.map.keyframes()[k].camera_from_world.matrix(),
              inline_scene.map.keyframes()[k].camera_from_world.matrix());
  ASSERT_EQ(beside_scene.map.num_points(), inline_scene.map.num_points());
  for (const auto& [id, point] : beside_scene.map.points()) {
    ASSERT_NE(inline_scene.map.FindPoint(id), nullptr);
    EXPECT_EQ(point.position_in_world, inline_scene.map.FindPoint(id)->position_in_world);
  }
  EXPECT_EQ(packet.keyframe_world_from_camera.matrix(), at_once.keyframe_world_from_camera.matrix());
  // The correction is how the keyframe moved: it takes the old pose to the refined one.
  EXPECT_TRUE((packet.world_correction * off.inverse()).isApprox(packet.keyframe_world_from_camera, 1e-12));
}

// What the tracker added while the BA ran (a keyframe 10 cm further on and a point it
// created) was placed relative to the keyframe's old pose and moves with it.
TEST(LocalMapper, MovesWhatWasAddedMeanwhileWithTheRefinedKeyframe) {
  Scene s;
  BuildScene(s, 5, 0.0, 4);
  const Pose off = PoseFromAxisAngle({0, 0, 0}, {0.03, 0, 0}) * s.true_camera_from_world[4];
  s.map.SetKeyframePose(4, off);
  Executor executor(1);
  LocalMapper mapper(s.camera, MergedAfter(3), &executor);
  EXPECT_EQ(mapper.Process(10, true, s.map).status, MappingStatus::kIdle);
  const Pose newer_from_old = PoseFromAxisAngle({0, 0.05, 0}, {-0.1, 0, 0});
  const Eigen::Vector3d point_in_old(0.2, -0.1, 2.5);  // in the old keyframe's camera
  const int64_t point = s.map.AddPoint(off.inverse() * point_in_old, cv::Mat(1, 32, CV_8UC1, cv::Scalar(0)), 12);
  Keyframe newer;
  newer.frame_index = 12;
  newer.camera_from_world = newer_from_old * off;
  newer.observations.push_back({point, s.camera.Project(newer_from_old * point_in_old), 2.5});
  s.map.AddKeyframe(newer);
  // The new keyframe is due before the delay: the pending BA joins first.
  const MappingPacket packet = mapper.Process(12, true, s.map);
  ASSERT_EQ(packet.status, MappingStatus::kAdjusted) << packet.failure;
  EXPECT_TRUE(packet.started);
  EXPECT_EQ(packet.keyframe_frame, 10u);
  // The refined keyframe is back at the truth (noise-free: within 0.3% of the 3 cm offset)...
  const Pose refined = s.map.keyframes()[4].camera_from_world;
  EXPECT_LT(TranslationError(refined, s.true_camera_from_world[4]), 1e-4);
  // ...and the newer keyframe and its point kept their place relative to it.
  EXPECT_TRUE((s.map.keyframes()[5].camera_from_world * refined.inverse()).isApprox(newer_from_old, 1e-9));
  EXPECT_LT((refined * s.map.FindPoint(point)->position_in_world - point_in_old).norm(), 1e-9);
}

TEST(LocalMapper, DropsABaWhoseMapWasReseededMeanwhile) {
  Scene s;
  BuildScene(s, 5, 0.0, 4);
  Executor executor(1);
  LocalMapper mapper(s.camera, MergedAfter(1), &executor);
  mapper.Process(10, true, s.map);
  s.map.Clear();
  const MappingPacket packet = mapper.Process(11, false, s.map);
  EXPECT_EQ(packet.status, MappingStatus::kFailed);
  EXPECT_EQ(packet.failure, "the map was re-seeded while the BA ran");
}

TEST(LocalMapper, SaysWhyWhenTheMapIsTooSmall) {
  Scene s;
  BuildScene(s, 2, 0.0, 4);
  const MappingPacket packet = LocalMapper(s.camera, MergedAfter(0)).Process(1, true, s.map);
  EXPECT_EQ(packet.status, MappingStatus::kFailed);
  EXPECT_EQ(packet.failure, "needs at least 3 keyframes (2 stay fixed)");
  EXPECT_EQ(ToString(packet.status), "failed");
}

}  // namespace
}  // namespace dynvo
