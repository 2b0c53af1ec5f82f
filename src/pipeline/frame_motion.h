#pragma once
// The camera's motion between consecutive frames as a homography, for the mask sources that do
// not difference frames (ground truth, the detector): KLT tracks of frame t-1's corners off its
// mask, then RANSAC. It is what the feature refill carries frame t-1's background by.

#include <optional>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "ego_motion/homography.h"
#include "ego_motion/klt_tracker.h"

namespace dynvo {

class FrameMotion {
 public:
  FrameMotion(const KltOptions& klt, const HomographyOptions& homography);

  // Frame t's homography from frame t-1 (current_from_previous), given frame t's grey image and
  // frame t-1's mask (corners on it are not tracked; may be empty); nullopt on the first frame or
  // when the estimate fails. Frame t becomes the previous frame.
  std::optional<Eigen::Matrix3d> Next(const cv::Mat& gray, const cv::Mat& previous_mask);

 private:
  KltOptions klt_;
  HomographyOptions homography_;
  TrackingPyramid previous_pyramid_;  // frame t-1's
};

}  // namespace dynvo
