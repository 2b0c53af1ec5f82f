#pragma once
// The paper's dynamic-object detector (§1, steps 1-5): KLT tracks -> homography (RANSAC + LM) ->
// motion-compensated differencing forward (and backward) -> Otsu -> erode/dilate -> fused mask;
// tracks inside the mask are dropped, H re-estimated from the static ones, the mask recomputed.

#include <string>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/executor.h"
#include "core/image_area.h"
#include "dynamic_mask/dynamic_mask_options.h"
#include "ego_motion/homography.h"
#include "ego_motion/klt_tracker.h"

namespace dynvo {

struct DynamicMaskInput {
  cv::Mat previous_gray;  // frame t-1, CV_8UC1
  cv::Mat current_gray;   // frame t, same size
  cv::Mat next_gray;      // frame t+1, only for BackwardMode::kTriplet (empty otherwise / at the sequence end)
  // Optional pyramids of the images above (BuildTrackingPyramid with the same KltOptions); when
  // given they are used instead of being rebuilt, e.g. the caller keeps frame t's for the next call.
  TrackingPyramid previous_pyramid, current_pyramid, next_pyramid;
  // Optional tracks t-1 -> t (previous = frame t-1 point, current = frame t point), e.g. the last
  // call's DynamicMaskResult::next_tracks under kTriplet; when given, t is not tracked into t-1 again.
  PointTracks previous_tracks;
  // The part of every frame with image data (e.g. without the black border of undistortion); pixels
  // outside it in either frame of a difference are never dynamic. Empty = the whole image.
  ImageArea image_area;
};

struct DynamicMaskResult {
  bool ok = false;
  std::string failure;           // why there is no mask this frame
  cv::Mat mask;                  // CV_8UC1 fused mask in frame t, 255 = dynamic (all zero when !ok)
  cv::Mat forward_mask;          // after morphology, frame t coordinates
  cv::Mat backward_mask;         // after morphology, frame t coordinates (empty when kNone or not available)
  std::string backward_failure;  // why backward_mask is empty although asked for ("" otherwise)
  cv::Mat compensated;           // warp of t-1 onto t (debug panel; at difference_level's size)
  cv::Mat difference;            // |t - warp(t-1)| (debug panel; at difference_level's size)
  Eigen::Matrix3d current_from_previous = Eigen::Matrix3d::Identity();
  int forward_threshold = 0;   // grey level used to binarise `difference` in the last round
  int rounds_run = 0;          // rounds whose mask was computed (fewer than asked when the static track set
                               // or H stopped changing, see DynamicMaskOptions::rounds_min_change_px)
  int num_tracks = 0;          // KLT tracks found (t-1 <-> t)
  PointTracks next_tracks;     // kTriplet: frame t's corners tracked into t+1 (previous = t, current = t+1),
                               // to pass as the next call's previous_tracks (saves one KLT run per frame)
  int num_static_tracks = 0;   // tracks outside the final mask
  double dynamic_ratio = 0.0;  // fraction of mask pixels
};

// The paper's detector: KLT tracks -> homography -> compensated differencing forward (and backward) -> fused mask;
// then tracks inside the mask's regions are dropped, H re-estimated from the static ones and the mask recomputed,
// `rounds` times. Corners are detected once in frame t and tracked into t-1 (and t+1 for kTriplet).
// Bad images or options throw InputError; too few tracks or a degenerate fit give ok = false with the reason.
// kTriplet without a next frame detects forward only (backward_failure says so). Deterministic:
// with `executor`, the forward direction runs on it beside the backward one (same result).
DynamicMaskResult DetectDynamicMask(const DynamicMaskInput& input, const KltOptions& klt,
                                    const HomographyOptions& homography, const DynamicMaskOptions& options,
                                    Executor* executor = nullptr);

// Share of the non-zero pixels of `mask` (CV_8UC1), in [0, 1]; 0 for an empty mask.
double DynamicRatio(const cv::Mat& mask);

}  // namespace dynvo
