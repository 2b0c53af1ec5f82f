#pragma once
// The features of one frame: keypoints, ORB descriptors, undistorted pixels and depth.

#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <Eigen/StdVector>
#include <opencv2/core.hpp>

namespace dynvo {

struct FrameFeatures {
  std::vector<cv::KeyPoint> keypoints;            // as detected (level-0 pixel coordinates, octave, angle, response)
  cv::Mat descriptors;                            // N x 32, CV_8UC1
  std::vector<Eigen::Vector2d> pixels;            // undistorted pixel positions
  std::vector<double> depths;                     // metres; 0 = no valid depth
  std::vector<Eigen::Vector3d> points_in_camera;  // back-projected (valid where depths > 0)
  size_t size() const { return keypoints.size(); }
};

}  // namespace dynvo
