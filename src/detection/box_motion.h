#pragma once
// A detection box carried from one frame into the next by the camera's motion as a homography.

#include <optional>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace dynvo {

// The axis-aligned box around `box`'s corners moved by current_from_previous (not clipped);
// nullopt when a corner maps behind the camera.
std::optional<cv::Rect2d> CarryBox(const cv::Rect2d& box, const Eigen::Matrix3d& current_from_previous);

}  // namespace dynvo
