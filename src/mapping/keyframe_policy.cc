#include "mapping/keyframe_policy.h"

#include <string>

#include "core/config_registry.h"
#include "core/error.h"

namespace dynvo {

namespace {
constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;
}  // namespace

void KeyframeOptions::Check() const {
  RequireOption(max_frames_between >= 1, "tracking.keyframes", "max_frames_between", ">= 1", max_frames_between);
  RequireOption(min_tracked_ratio >= 0.0 && min_tracked_ratio <= 1.0, "tracking.keyframes", "min_tracked_ratio",
                "in [0, 1]", min_tracked_ratio);
  RequireOption(min_translation_m > 0.0, "tracking.keyframes", "min_translation_m", "> 0", min_translation_m);
  RequireOption(min_rotation_deg > 0.0, "tracking.keyframes", "min_rotation_deg", "> 0", min_rotation_deg);
}

KeyframeDecision DecideKeyframe(const KeyframeOptions& options, int frames_since_keyframe, int num_tracked,
                                int num_tracked_reference, const Pose& keyframe_camera_from_world,
                                const Pose& current_camera_from_world) {
  KeyframeDecision decision;
  const Pose keyframe_from_current = keyframe_camera_from_world * current_camera_from_world.inverse();
  const double rotation_deg = RotationAngle(keyframe_from_current) * kDegreesPerRadian;
  if (frames_since_keyframe >= options.max_frames_between) {
    decision.reason = "frames";
  } else if (num_tracked_reference > 0 && num_tracked < options.min_tracked_ratio * num_tracked_reference) {
    decision.reason = "tracked_ratio";
  } else if (keyframe_from_current.translation().norm() >= options.min_translation_m) {
    decision.reason = "translation";
  } else if (rotation_deg >= options.min_rotation_deg) {
    decision.reason = "rotation";
  }
  decision.insert = !decision.reason.empty();
  return decision;
}

void BindConfigKeys(const std::string& prefix, KeyframeOptions* o, ConfigRegistry* r) {
  r->Bind(prefix + ".max_frames_between", &o->max_frames_between, "a keyframe at least this often");
  r->Bind(prefix + ".min_tracked_ratio", &o->min_tracked_ratio,
          "keyframe when tracked points fall below this share of the reference keyframe's");
}

}  // namespace dynvo
