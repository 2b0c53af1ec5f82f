#include "mapping/keyframe_policy.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace dynvo {
namespace {

TEST(KeyframeOptions, CheckNamesTheKey) {
  KeyframeOptions options;
  EXPECT_NO_THROW(options.Check());
  options.min_tracked_ratio = 1.5;
  try {
    options.Check();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("keyframes.min_tracked_ratio must be in [0, 1]"), std::string::npos);
  }
  options = {};
  options.max_frames_between = 0;
  EXPECT_THROW(options.Check(), InputError);
  options = {};
  options.min_translation_m = 0;
  EXPECT_THROW(options.Check(), InputError);
  options = {};
  options.min_rotation_deg = -1;
  EXPECT_THROW(options.Check(), InputError);
}

TEST(DecideKeyframe, EachCriterionFires) {
  const KeyframeOptions options;  // 10 frames, 0.7, 5 cm, 5 deg
  const Pose keyframe = PoseFromAxisAngle({0.1, 0, 0}, {0.2, 0, 0});
  // Close to the keyframe, well tracked, recent: no keyframe.
  const Pose near = PoseFromAxisAngle({0.1, 0.01, 0}, {0.22, 0, 0});
  EXPECT_FALSE(DecideKeyframe(options, 3, 90, 100, keyframe, near).insert);
  EXPECT_EQ(DecideKeyframe(options, 10, 90, 100, keyframe, near).reason, "frames");
  EXPECT_EQ(DecideKeyframe(options, 3, 69, 100, keyframe, near).reason, "tracked_ratio");
  EXPECT_FALSE(DecideKeyframe(options, 3, 69, 0, keyframe, near).insert);  // no reference
  const Pose moved = PoseFromAxisAngle({0.1, 0, 0}, {0.2, 0.06, 0});
  EXPECT_EQ(DecideKeyframe(options, 3, 90, 100, keyframe, moved).reason, "translation");
  // Turned 6 degrees about the camera centre: the translation of camera_from_world changes
  // but the camera does not move.
  const Pose turned_rot = PoseFromAxisAngle({0, 6.0 / 180.0 * 3.14159265358979323846, 0}, {0, 0, 0});
  const Pose turned = turned_rot * keyframe;
  const KeyframeDecision d = DecideKeyframe(options, 3, 90, 100, keyframe, turned);
  EXPECT_TRUE(d.insert);
  EXPECT_EQ(d.reason, "rotation");
}

}  // namespace
}  // namespace dynvo
