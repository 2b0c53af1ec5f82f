#pragma once
// The part of an image that holds image data: a convex polygon in pixel coordinates. An
// undistorted Kinect frame has a black border where the remap had no source pixel; frame
// differencing must not read it as motion.

#include <vector>

#include <opencv2/core.hpp>

namespace dynvo {

// Convex polygon (pixel centres, in order) of the pixels with image data; empty = the whole image.
using ImageArea = std::vector<cv::Point2f>;

// A convex polygon every pixel of which (as cv::fillConvexPoly rasterises it) is non-zero in the
// CV_8UC1 `valid`: the convex hull of the non-zero pixels, shrunk towards its centroid until it fits
// (for a convex region, such as the image of an undistorted sensor, it covers the region up to
// its rasterised edge; a non-convex one may get a much smaller polygon).
// Empty when every pixel is non-zero (the whole image); throws InputError when none is, or when
// even a tiny polygon around the hull's centroid does not fit.
ImageArea ConvexAreaInside(const cv::Mat& valid);

// `area` in the coordinates of an image scaled by `scale` (x' = scale * x); empty stays empty.
ImageArea ScaleArea(const ImageArea& area, double scale);

// Sets the pixels of the CV_8UC1 `mask` inside `area` to 255 (every pixel when `area` is empty);
// the others keep their value.
void FillArea(const ImageArea& area, cv::Mat* mask);

// CV_8UC1 image of `size`: 255 inside `area` (every pixel when `area` is empty), 0 outside.
cv::Mat AreaMask(const ImageArea& area, const cv::Size& size);

}  // namespace dynvo
