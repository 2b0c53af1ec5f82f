#pragma once
// Regions of interest of a dynamic mask (paper §1.2): its connected non-zero regions. A point lies
// inside one of them exactly when the mask pixel under it is non-zero.

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

namespace dynvo {

// True when `point` (pixel coordinates, rounded to the nearest pixel) lies on a non-zero pixel of
// the CV_8UC1 `mask`; points outside the image are not inside any region.
bool InMaskRegion(const cv::Mat& mask, const cv::Point2f& point);

// Per point: 1 when it lies outside every region of `mask` (static), 0 inside (dynamic).
// An empty mask keeps every point.
std::vector<uint8_t> StaticPointFlags(const cv::Mat& mask, const std::vector<cv::Point2f>& points);

// The connected regions (8-connected non-zero pixels) of `regions` that share at least one pixel
// with a non-zero pixel of `seeds`, as a CV_8UC1 mask (255 = kept); the others are dropped. Both
// CV_8UC1 of one size; an empty `seeds` keeps nothing. Throws InputError otherwise.
cv::Mat RegionsTouching(const cv::Mat& regions, const cv::Mat& seeds);

// The union of two binary masks of one size; an empty one adds nothing (the other is returned).
cv::Mat MaskUnion(const cv::Mat& a, const cv::Mat& b);

}  // namespace dynvo
