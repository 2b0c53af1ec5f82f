#pragma once
// The camera's motion from the static scene's depth. Features can mislead the pose where a
// moving person holds most of the texture (a plain room): the pose follows the person. The
// walls and floor, which hold most of the pixels, do not move: a keyframe's depth, sampled on a
// grid off its dynamic mask, aligned point-to-plane onto the frame's depth (projective
// association, Gauss-Newton, weights by the Kinect's depth noise) gives the motion the static
// scene supports, and the share of it that lines up scores any candidate motion.

#include <optional>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/camera.h"
#include "core/pose.h"

namespace dynvo {

// A frame's depth (CV_32FC1 metres, 0 = none) and its dynamic mask (CV_8UC1, non-zero =
// dynamic; empty = none), as the tracker takes them.
struct FrameDepth {
  cv::Mat depth;
  cv::Mat mask;
};

// Points in camera coordinates behind every 8th pixel (both axes) of `frame` with depth and off
// its mask. Throws InputError when the images are not of the camera's size and type.
std::vector<Eigen::Vector3f> SampleStaticDepth(const Camera& camera, const FrameDepth& frame);

// The share of `samples` (in the reference camera) that `current_from_reference` moves in front
// of the camera, into the image onto a pixel with depth off the frame's mask, whose depth there
// agrees with it within 1 cm + 2% (the Kinect's noise and a depth edge's half pixel); nullopt
// when fewer than 200 samples land on such depth (too little of the scene to judge). Throws
// InputError when the frame's images are not of the camera's size and type.
std::optional<double> DepthAgreement(const Camera& camera, const std::vector<Eigen::Vector3f>& samples,
                                     const FrameDepth& frame, const Pose& current_from_reference);

// The motion that aligns `samples` (in the reference camera) onto the frame's depth off its
// mask, point-to-plane, from `initial_current_from_reference` (at most 10 Gauss-Newton steps,
// associations renewed each step, residuals over the depth's noise with a Huber loss, pairs more
// than 5 cm + 5% apart left out). nullopt when fewer than 200 samples associate or the static
// scene leaves a direction of motion unconstrained (planes that all share it). Deterministic.
// Throws InputError as DepthAgreement.
std::optional<Pose> AlignStaticDepth(const Camera& camera, const std::vector<Eigen::Vector3f>& samples,
                                     const FrameDepth& frame, const Pose& initial_current_from_reference);

}  // namespace dynvo
