#pragma once
// When a tracked frame becomes a keyframe.

#include <string>

#include "core/pose.h"

namespace dynvo {

class ConfigRegistry;

struct KeyframeOptions {
  int max_frames_between = 10;      // frames; a keyframe at least this often (>= 1)
  double min_tracked_ratio = 0.7;   // tracked / reference inliers below this -> keyframe, [0, 1]
  double min_translation_m = 0.05;  // metres moved since the last keyframe -> keyframe (> 0)
  double min_rotation_deg = 5.0;    // degrees turned since the last keyframe -> keyframe (> 0)
  // Throws InputError naming the key ("tracking.keyframes.max_frames_between ...") when out of range.
  void Check() const;
};

// The config keys of the keyframe policy (section "tracking.keyframes"): max_frames_between, min_tracked_ratio.
void BindConfigKeys(const std::string& prefix, KeyframeOptions* options, ConfigRegistry* registry);

struct KeyframeDecision {
  bool insert = false;
  std::string reason;  // which criterion fired ("frames", "tracked_ratio", "translation",
                       // "rotation"), "" when insert is false
};

// Whether the current frame should become a keyframe: true when any criterion of `options`
// fires. `num_tracked` are the frame's inliers to the map, `num_tracked_reference` those of
// the last keyframe when it was made (<= 0: the ratio criterion is skipped).
KeyframeDecision DecideKeyframe(const KeyframeOptions& options, int frames_since_keyframe, int num_tracked,
                                int num_tracked_reference, const Pose& keyframe_camera_from_world,
                                const Pose& current_camera_from_world);

}  // namespace dynvo
