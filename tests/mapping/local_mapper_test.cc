#include "mapping/local_mapper.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "keyframe_scene.h"

namespace dynvo {
namespace {

using test::BuildScene;
using test::Scene;
using test::TranslationError;

TEST(LocalMapper, RejectsInvalidOptions) {
  BundleAdjustmentOptions options;
  options.window_keyframes = 0;
  EXPECT_THROW(LocalMapper(Camera{}, options), InputError);
}

// The newest keyframe, 3 cm off its true pose, comes back to it; the mapper hands its pose on.
TEST(LocalMapper, AdjustsTheNewestKeyframeOfATrackedFrame) {
  Scene s;
  BuildScene(s, 5, 0.0, 4);
  const size_t newest = s.map.num_keyframes() - 1;
  s.map.SetKeyframePose(newest, PoseFromAxisAngle({0, 0, 0}, {0.03, 0, 0}) * s.true_camera_from_world[newest]);
  const LocalMapper mapper(s.camera, {});
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

TEST(LocalMapper, SaysWhyWhenTheMapIsTooSmall) {
  Scene s;
  BuildScene(s, 2, 0.0, 4);
  const MappingPacket packet = LocalMapper(s.camera, {}).Process(1, true, s.map);
  EXPECT_EQ(packet.status, MappingStatus::kFailed);
  EXPECT_EQ(packet.failure, "needs at least 3 keyframes (2 stay fixed)");
  EXPECT_EQ(ToString(packet.status), "failed");
}

}  // namespace
}  // namespace dynvo
