#pragma once
// Morphology of the binary difference (paper §1.2): erosion drops specks of noise, dilation
// grows the surviving regions (paper: erode kernel 4 x 2 iterations, dilate kernel 16 x 1).

#include <opencv2/core.hpp>

#include "dynamic_mask/dynamic_mask_options.h"

namespace dynvo {

// The size x size structuring element of `shape` (CV_8UC1), anchored at its centre (size/2).
cv::Mat MorphKernel(MorphShape shape, int size);

// Erodes a binary CV_8UC1 mask in place `iterations` times; size 0 or iterations 0 leave it as is.
// Outside the image counts as set, so the border itself does not erode regions.
void ErodeMask(MorphShape shape, int size, int iterations, cv::Mat* mask);

// Dilates a binary CV_8UC1 mask in place `iterations` times; size 0 or iterations 0 leave it as is.
void DilateMask(MorphShape shape, int size, int iterations, cv::Mat* mask);

// Erosion, then dilation, with the kernels of `options`.
void CleanMask(const DynamicMaskOptions& options, cv::Mat* mask);

}  // namespace dynvo
