#pragma once
// Binarisation of the difference image (paper eq. 2): D = 255 where I_diff > th, th from Otsu's
// method over the valid pixels only, or fixed.

#include <opencv2/core.hpp>

#include "dynamic_mask/dynamic_mask_options.h"

namespace dynvo {

// Otsu's threshold of a CV_8UC1 image over the pixels where `valid` is non-zero (all pixels when
// empty): the grey level t maximising the between-class variance of {<= t} and {> t} (the first
// such t, like cv::THRESH_OTSU). 0 when fewer than two grey levels occur.
int OtsuThreshold(const cv::Mat& image, const cv::Mat& valid = cv::Mat());

// OtsuThreshold(image, valid) for an image that is 0 wherever `valid` is 0 (as AbsoluteDifference
// writes it), computed more cheaply; the result is undefined for other images.
int OtsuThresholdZeroOutsideValid(const cv::Mat& image, const cv::Mat& valid);

// The threshold `options` asks for: Otsu over the valid pixels (raised to min_otsu_threshold) or fixed.
// `difference` must be 0 outside `valid` (AbsoluteDifference's output).
int DifferenceThreshold(const cv::Mat& difference, const cv::Mat& valid, const DynamicMaskOptions& options);

// 255 where image > threshold, else 0 (CV_8UC1). Writes into `binary`, reusing its buffer.
void Binarize(const cv::Mat& image, int threshold, cv::Mat* binary);

}  // namespace dynvo
