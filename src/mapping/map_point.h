#pragma once
// A 3D point of the local map: where it is, what it looks like, who observes it.

#include <cstdint>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace dynvo {

struct MapPoint {
  int64_t id = -1;                                              // unique in its map, increasing
  Eigen::Vector3d position_in_world = Eigen::Vector3d::Zero();  // metres
  cv::Mat descriptor;                                           // 1 x 32, CV_8UC1 (ORB)
  float angle_deg = 0.0f;        // ORB orientation of the observation the descriptor is from, degrees
  int observations = 0;          // number of kept keyframes that observe it
  int64_t first_frame = -1;      // index of the frame that created it
  int64_t last_seen_frame = -1;  // index of the last frame it was matched in
  int unconfirmed_frames = 0;    // frames that must still confirm it before tracking trusts it
                                 // (0 = trusted; see tracking/new_point_confirmation.h)
};

}  // namespace dynvo
