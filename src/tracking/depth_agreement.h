#pragma once
// How much of the static scene's depth a camera motion explains. Features can mislead the pose
// where a moving person holds most of the texture (a plain room): the pose then follows the
// person, but the walls and floor, which cover most of the image, no longer line up. Frame
// t-1's depth, sampled on a grid off its dynamic mask, is moved by a candidate motion into
// frame t and compared with frame t's depth; the share that agrees scores the motion.

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/camera.h"
#include "core/pose.h"

namespace dynvo {

class ConfigRegistry;

struct DepthCheckOptions {
  bool enabled = true;  // a pose the static depth contradicts is rejected (see ContradictsDepth)
};

// The config keys of the depth check (section "tracking.depth_check"): enabled.
void BindConfigKeys(const std::string& prefix, DepthCheckOptions* options, ConfigRegistry* registry);

// A frame's depth (CV_32FC1 metres, 0 = none) and its dynamic mask (CV_8UC1, non-zero =
// dynamic; empty = none), as the tracker takes them.
struct FrameDepth {
  cv::Mat depth;
  cv::Mat mask;
};

// Points in camera coordinates behind every 8th pixel (both axes) of `frame` with depth and off
// its mask. Throws InputError when the images are not of the camera's size and type.
std::vector<Eigen::Vector3f> SampleStaticDepth(const Camera& camera, const FrameDepth& frame);

// The share of `samples` (frame t-1's, SampleStaticDepth) that `current_from_previous` moves in
// front of the camera, into the image onto a pixel with depth, whose depth there agrees with
// it within 1 cm + 2% (the Kinect's noise and a depth edge's half pixel); nullopt when fewer
// than 200 samples land on depth (too little of the scene to judge). Throws InputError when
// `depth` is not of the camera's size and type.
std::optional<double> DepthAgreement(const Camera& camera, const std::vector<Eigen::Vector3f>& samples,
                                     const cv::Mat& depth, const Pose& current_from_previous);

// True when less than half as much of the static depth agrees at a pose estimate as at the
// motion model's prediction: the estimate followed something that moved. Unknown scores
// (nullopt) contradict nothing.
bool ContradictsDepth(const std::optional<double>& estimate_agreement,
                      const std::optional<double>& prediction_agreement);

}  // namespace dynvo
