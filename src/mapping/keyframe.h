#pragma once
// A keyframe: a frame whose pose and observations of map points are kept for mapping.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "core/pose.h"
#include "lines/line_segment.h"

namespace dynvo {

// One keyframe observation: map point `point_id` seen at an undistorted pixel.
struct KeyframeObservation {
  int64_t point_id = -1;                            // MapPoint::id
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();  // undistorted pixel, pixels
  double depth = 0.0;                               // measured depth, metres; 0 = none
};

// A keyframe's observation of a line another keyframe anchors (its lines_in_camera[line]).
struct KeyframeLineObservation {
  int64_t anchor_keyframe_id = -1;                     // Keyframe::id of the anchor
  size_t line = 0;                                     // index into the anchor's lines_in_camera
  Eigen::Vector3d observed = Eigen::Vector3d::Zero();  // the image line (ImageLineCoefficients), undistorted pixels
};

struct Keyframe {
  int64_t id = -1;           // unique in its map, increasing (set by LocalMap)
  int64_t frame_index = -1;  // index of the input frame
  double stamp = 0.0;        // seconds
  Pose camera_from_world = Pose::Identity();
  std::vector<KeyframeObservation> observations;  // at most one per map point
  // Line segments it saw with depth that no earlier keyframe's line explained, in its camera
  // coordinates: they move with the keyframe when the local BA moves it (features.lines).
  std::vector<Line3d> lines_in_camera;
  std::vector<KeyframeLineObservation> line_observations;  // of earlier keyframes' lines, pose inliers
};

}  // namespace dynvo
