#pragma once
// A keyframe as a camera exposing every row at the image's stamp would have seen it. A
// rolling-shutter camera (core/rolling_shutter.h) that turns sees each row from its own pose,
// so tracking's one pose per image is off by a turn that shears the image; over a loop the
// shear adds up to drift no closure can see (on the generated loops, most of the error left
// after closing: docs/findings.md). Turned back to the stamp, the keyframes' observations let
// the full BA place them where the scene says.

#include <Eigen/Core>

#include "core/camera.h"
#include "loop/loop_keyframe.h"

namespace dynvo {

// `keyframe` with each observation of tracking's (pixel, and depth when measured) and each
// feature (pixel and point) turned by StampFromRow of the row it was seen in, for a camera
// turning at `angular_velocity` (rad/s, its own frame) with camera.rolling_shutter_readout_s.
// Unchanged for a global shutter or no turn.
LoopKeyframe KeyframeAtStamp(const LoopKeyframe& keyframe, const Eigen::Vector3d& angular_velocity,
                             const Camera& camera);

}  // namespace dynvo
