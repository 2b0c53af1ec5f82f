#include "dynamic_mask/frame_difference.h"

#include "core/error.h"

namespace dynvo {

void AbsoluteDifference(const cv::Mat& a, const cv::Mat& b, const cv::Mat& valid, cv::Mat* difference) {
  if (a.type() != CV_8UC1 || b.type() != CV_8UC1 || a.size() != b.size() || a.empty())
    throw InputError("AbsoluteDifference needs two non-empty CV_8UC1 images of the same size");
  if (!valid.empty() && (valid.type() != CV_8UC1 || valid.size() != a.size()))
    throw InputError("AbsoluteDifference: valid mask must be CV_8UC1 of the image size");
  cv::absdiff(a, b, *difference);
  // A bitwise AND with the 0/255 valid mask zeroes the pixels without a source.
  if (!valid.empty()) cv::bitwise_and(*difference, valid, *difference);
}

cv::Mat AbsoluteDifference(const cv::Mat& a, const cv::Mat& b, const cv::Mat& valid) {
  cv::Mat difference;
  AbsoluteDifference(a, b, valid, &difference);
  return difference;
}

}  // namespace dynvo
