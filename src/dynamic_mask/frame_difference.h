#pragma once
// Frame differencing (paper eq. 1): I_diff = |I_t - warp(I_{t-1})|, only where the warp had source pixels.

#include <opencv2/core.hpp>

namespace dynvo {

// |a - b| per pixel for two CV_8UC1 images of the same size; 0 where `valid` (CV_8UC1, same size,
// values 0 or 255) is zero, when given. Writes into `difference`, reusing its buffer when it fits.
void AbsoluteDifference(const cv::Mat& a, const cv::Mat& b, const cv::Mat& valid, cv::Mat* difference);

// Same, returning a fresh image.
cv::Mat AbsoluteDifference(const cv::Mat& a, const cv::Mat& b, const cv::Mat& valid = cv::Mat());

}  // namespace dynvo
