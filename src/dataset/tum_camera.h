#pragma once
// The cameras of the TUM RGB-D benchmark (Freiburg 1, 2, 3 Kinects), as published on the
// TUM site ("File Formats" / "Intrinsic Camera Calibration").

#include <string>

#include "core/camera.h"

namespace dynvo {

// TUM intrinsics by sequence folder name, 640x480: a name containing "freiburg1" gives fr1
// (517.3 516.5 318.6 255.3; distortion 0.2624 -0.9531 -0.0054 0.0026 1.1633), "freiburg2"
// gives fr2 (520.9 521.0 325.1 249.7; distortion 0.2312 -0.7849 -0.0033 -0.0001 0.9172),
// "freiburg3" gives fr3 (535.4 539.2 320.1 247.6; no distortion, images pre-rectified), any
// other name the ROS default (525 525 319.5 239.5). `recognised`, when given, tells whether
// one of the three names matched.
Camera TumCameraForSequence(const std::string& folder_name, bool* recognised = nullptr);

// The depth PNG value per metre of a TUM sequence by folder name: 5208 for "freiburg2" (that
// Kinect reads depth about 4% too far; ORB-SLAM2's TUM2.yaml uses the same factor), else the
// published 5000.
double TumDepthFactorForSequence(const std::string& folder_name);

}  // namespace dynvo
