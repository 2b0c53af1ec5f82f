#pragma once
// The people of the current frame when the detector does not run on every frame (or fails on
// one): the last detection, carried from frame to frame by the camera's motion as a homography
// (box_motion.h), with its age in frames.

#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "detection/person_detector.h"

namespace dynvo {

class CarriedDetections {
 public:
  // The current frame was detected: these are its people, age 0.
  void Detected(std::vector<Detection> people);
  // The current frame was not detected: the last people moved into it (an `image`-sized frame)
  // by `current_from_previous`, one frame older; without a motion (nullptr) they are dropped.
  // Nothing happens before the first detection.
  void Carry(const Eigen::Matrix3d* current_from_previous, const cv::Size& image);

  const std::vector<Detection>& people() const { return people_; }
  // Frames since the people were detected (0: this frame; -1: never).
  int age() const { return age_; }

 private:
  std::vector<Detection> people_;
  int age_ = -1;
};

}  // namespace dynvo
