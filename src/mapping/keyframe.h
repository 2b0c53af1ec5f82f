#pragma once
// A keyframe: a frame whose pose and observations of map points are kept for mapping.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/pose.h"

namespace dynvo {

// One keyframe observation: map point `point_id` seen at an undistorted pixel.
struct KeyframeObservation {
  int64_t point_id = -1;                            // MapPoint::id
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();  // undistorted pixel, pixels
  double depth = 0.0;                               // measured depth, metres; 0 = none
};

struct Keyframe {
  int64_t id = -1;           // unique in its map, increasing (set by LocalMap)
  int64_t frame_index = -1;  // index of the input frame
  double stamp = 0.0;        // seconds
  Pose camera_from_world = Pose::Identity();
  std::vector<KeyframeObservation> observations;  // at most one per map point
};

}  // namespace dynvo
