#include "dynamic_mask/mask_morphology.h"

#include <opencv2/imgproc.hpp>

#include "core/error.h"

namespace dynvo {
namespace {

int CvShape(MorphShape shape) {
  switch (shape) {
    case MorphShape::kRect:
      return cv::MORPH_RECT;
    case MorphShape::kEllipse:
      return cv::MORPH_ELLIPSE;
    case MorphShape::kCross:
      return cv::MORPH_CROSS;
  }
  return cv::MORPH_RECT;
}

void CheckMask(const cv::Mat* mask) {
  if (mask == nullptr || mask->type() != CV_8UC1) throw InputError("mask morphology needs a CV_8UC1 mask");
}

}  // namespace

cv::Mat MorphKernel(MorphShape shape, int size) {
  if (size < 1) throw InputError("MorphKernel: size must be >= 1, got " + std::to_string(size));
  return cv::getStructuringElement(CvShape(shape), cv::Size(size, size));
}

void ErodeMask(MorphShape shape, int size, int iterations, cv::Mat* mask) {
  CheckMask(mask);
  if (size <= 0 || iterations <= 0 || mask->empty()) return;
  cv::erode(*mask, *mask, MorphKernel(shape, size), cv::Point(-1, -1), iterations);
}

void DilateMask(MorphShape shape, int size, int iterations, cv::Mat* mask) {
  CheckMask(mask);
  if (size <= 0 || iterations <= 0 || mask->empty()) return;
  cv::dilate(*mask, *mask, MorphKernel(shape, size), cv::Point(-1, -1), iterations);
}

void CleanMask(const DynamicMaskOptions& options, cv::Mat* mask) {
  ErodeMask(options.erode_shape, options.erode_kernel_size, options.erode_iterations, mask);
  DilateMask(options.dilate_shape, options.dilate_kernel_size, options.dilate_iterations, mask);
}

}  // namespace dynvo
