#pragma once
// A detection box carried from one frame into the next by the camera's motion as a homography.

#include <optional>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "detection/person_detector.h"

namespace dynvo {

// The axis-aligned box around `box`'s corners moved by current_from_previous (not clipped);
// nullopt when a corner maps behind the camera.
std::optional<cv::Rect2d> CarryBox(const cv::Rect2d& box, const Eigen::Matrix3d& current_from_previous);

// `detections` with their boxes carried into the next frame and clipped to its `image` size;
// those that fall behind the camera or outside the image are dropped.
std::vector<Detection> CarryDetections(const std::vector<Detection>& detections,
                                       const Eigen::Matrix3d& current_from_previous, const cv::Size& image);

}  // namespace dynvo
