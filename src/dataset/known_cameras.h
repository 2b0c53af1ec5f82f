#pragma once
// The RGB-D cameras of public benchmarks, as their authors publish them: the TUM RGB-D
// Kinects (freiburg1, 2, 3; TUM site, "File Formats"), the Bonn RGB-D Dynamic dataset's
// Xtion, and the ROS default pinhole. All 640x480.

#include <optional>
#include <string>
#include <vector>

#include "core/camera.h"

namespace dynvo {

struct KnownCamera {
  std::string name;         // "fr1", "fr2", "fr3", "bonn", "ros_default": camera.source's value
  std::string description;  // e.g. "TUM RGB-D freiburg1 Kinect"
  Camera camera;
  double depth_factor = 5000.0;  // depth PNG value per metre
};

// The names KnownCameraByName() accepts, in a fixed order.
std::vector<std::string> KnownCameraNames();

// fr1: 517.3 516.5 318.6 255.3, distortion 0.2624 -0.9531 -0.0054 0.0026 1.1633.
// fr2: 520.9 521.0 325.1 249.7, distortion 0.2312 -0.7849 -0.0033 -0.0001 0.9172, depth
//      factor 5208 (that Kinect reads depth about 4% too far; ORB-SLAM2's TUM2.yaml too).
// fr3: 535.4 539.2 320.1 247.6, no distortion (images pre-rectified).
// bonn: 542.822841 542.576870 315.593520 237.756098, distortion 0.039903 -0.099343
//      -0.000730 -0.000144 0.
// ros_default: 525 525 319.5 239.5, no distortion.
// Depth factor 5000 unless given above. nullopt for any other name.
std::optional<KnownCamera> KnownCameraByName(const std::string& name);

// The camera a sequence folder's name announces: "freiburg1", "freiburg2", "freiburg3"
// anywhere in it (TUM's rgbd_dataset_freiburgN_*), or a name starting "rgbd_bonn_" (Bonn's).
// nullopt when the name says nothing (the ROS default is never guessed).
std::optional<KnownCamera> KnownCameraForFolder(const std::string& folder_name);

}  // namespace dynvo
