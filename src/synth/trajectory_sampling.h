#pragma once
// Camera poses between groundtruth samples.

#include "dataset/trajectory_io.h"

namespace dynvo {

// The pose at `stamp`, interpolated (translation linearly, rotation by slerp) between the
// two groundtruth samples around it. False when `stamp` lies outside the trajectory or the
// samples around it are more than `max_gap_s` seconds apart. Stamps must increase.
bool InterpolatePose(const Trajectory& trajectory, double stamp, double max_gap_s, Pose* world_from_camera);

}  // namespace dynvo
