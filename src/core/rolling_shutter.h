#pragma once
// Rolling shutter: a CMOS sensor (the Kinect v1's colour camera among them) reads its rows out
// one after another, so a moving camera sees each row from its own pose. Row r of an image of
// H rows stamped t is exposed at t + readout * (r / (H - 1) - 0.5): the middle row at the
// stamp. At 60 deg/s over a 28 ms readout the bottom row is seen 1.7 degrees away from the
// top one, about 15 px at 640x480.

#include <Eigen/Core>

#include "core/camera.h"

namespace dynvo {

// Seconds from the image stamp at which (fractional) row `row` of `height` rows is exposed
// when the rows are read out over `readout_s`; 0 for the middle row or a readout of 0.
double RowExposureOffset(double row, int height, double readout_s);

// The rotation taking a point from the camera that exposed image row `row` into the camera at
// the image's stamp, for a camera turning at `angular_velocity` (rad/s, axis times speed, in
// its own frame) and reading its rows out over camera.rolling_shutter_readout_s. Translation
// over the readout is left out (millimetres for a hand-held camera). Identity for the middle
// row, a global shutter or no turn.
Eigen::Matrix3d StampFromRow(const Camera& camera, const Eigen::Vector3d& angular_velocity, double row);

}  // namespace dynvo
