#pragma once
// What place recognition keeps of a keyframe: its features with depth (seen in its own camera
// frame), a small depth image, and where tracking put it.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/StdVector>
#include <opencv2/core.hpp>

#include "core/pose.h"
#include "features/frame_features.h"
#include "mapping/keyframe.h"

namespace dynvo {

struct LoopKeyframe {
  size_t number = 0;                          // position among the closer's keyframes (0 = first)
  size_t frame = 0;                           // index of its input frame
  double stamp = 0.0;                         // seconds
  Pose world_from_camera = Pose::Identity();  // as tracked (the online trajectory)
  double path_m = 0.0;                        // camera path length from the first keyframe, metres
  double turned_rad = 0.0;                    // summed rotation from the first keyframe, radians
  // The static features with depth (those off the dynamic mask): undistorted pixels, points
  // in this keyframe's camera frame, ORB descriptors (N x 32 CV_8UC1), row i for feature i.
  std::vector<Eigen::Vector2d> pixels;
  std::vector<Eigen::Vector3d> points_in_camera;
  cv::Mat descriptors;
  // LBD descriptors (N x 32 CV_8UC1) of its line segments off the mask when lines are on
  // (features.lines), else empty: they vote in place recognition with the ORB ones.
  cv::Mat line_descriptors;
  // Tracking's observations of map points in this keyframe (the matched ones and those it made).
  std::vector<KeyframeObservation> observations;
  cv::Mat depth;             // CV_32FC1 metres (0 = none), the frame's depth reduced by depth_scale
  double depth_scale = 1.0;  // depth pixel = full-size pixel * depth_scale
};

// A frame's LoopKeyframe: its features with depth (in order), its depth image reduced
// `depth_reduction` times (nearest pixel), path and turn from `previous` (the keyframe before,
// null for the first) added to that one's.
LoopKeyframe MakeLoopKeyframe(size_t number, size_t frame, double stamp, const Pose& world_from_camera,
                              const FrameFeatures& features, const cv::Mat& depth, int depth_reduction,
                              const LoopKeyframe* previous);

}  // namespace dynvo
