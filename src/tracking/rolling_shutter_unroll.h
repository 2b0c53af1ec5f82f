#pragma once
// Rolling-shutter correction of a frame's features. A rolling-shutter camera (Kinect v1's colour
// camera among them) exposes its rows one after another, so a turning camera sees each row from
// another orientation and the image is sheared: at 60 deg/s over a 28 ms readout the bottom row
// is seen 1.7 deg away from the top one, about 15 px at 640x480. Tracking with one pose per
// image then tilts the pose with the turn. The features are moved to where a camera exposing
// every row at the image's stamp would have seen them, under the turn of the motion model.

#include <Eigen/Core>

#include "core/camera.h"
#include "features/frame_features.h"

namespace dynvo {

// Rotation of the camera seen by image row `row` relative to the camera at the image's stamp
// (stamp_from_row), for rows exposed top to bottom over `readout_s`, the middle row at the
// stamp, turning at `angular_velocity` (rad/s, axis times speed, in the camera's frame).
Eigen::Matrix3d RowRotation(const Camera& camera, const Eigen::Vector3d& angular_velocity, double readout_s,
                            double row);

// Moves each feature's pixel, back-projected point and depth by RowRotation of its row; the
// keypoints (as detected) and descriptors are kept. Translation over the readout is neglected
// (millimetres for a hand-held camera). Nothing changes when `readout_s` or the velocity is 0.
void UnrollRollingShutter(const Camera& camera, const Eigen::Vector3d& angular_velocity, double readout_s,
                          FrameFeatures* features);

}  // namespace dynvo
