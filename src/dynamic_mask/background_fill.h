#pragma once
// The static background behind the dynamic mask: frame t with its masked pixels taken from the
// earlier frames, carried into frame t by the ego-motion homography. Features described on it
// near the mask see the scene's static part where frame t shows what moves.

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/image_area.h"
#include "dynamic_mask/motion_compensation.h"

namespace dynvo {

// The margin the pipeline fills around the mask: the mask's edge pixels blend what moves into
// the background (with ground-truth masks, 1 px gives 1.05-1.15x of the twin's RPE on the
// rotating camera, scene seeds 1-3; the bare mask 1.09-1.20x).
constexpr int kBackgroundFillMarginPx = 1;

// Frame t (`current_gray`, CV_8UC1) with the non-zero pixels of `mask` (CV_8UC1, same size), grown
// by `margin_px` on every side, replaced by `previous_background` warped by `current_from_previous`
// (x_t ~ H x_t-1). `previous_background` is frame t-1's result of this function (or frame t-1 itself
// when it had no mask), so what was seen behind a moving region in any earlier frame is carried on.
// Masked pixels the warp has no source for, or outside `area`, keep frame t's value. An empty mask
// returns `current_gray` itself; an empty `previous_background` a copy of it. Only the grown mask's
// bounding box is warped (the same pixels as a warp of the whole frame).
cv::Mat FillMaskFromBackground(const cv::Mat& current_gray, const cv::Mat& mask, const cv::Mat& previous_background,
                               const Eigen::Matrix3d& current_from_previous, int margin_px, const ImageArea& area = {});

}  // namespace dynvo
