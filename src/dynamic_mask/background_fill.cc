#include "dynamic_mask/background_fill.h"

#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "dynamic_mask/mask_morphology.h"

namespace dynvo {

cv::Mat FillMaskFromBackground(const cv::Mat& current_gray, const cv::Mat& mask, const cv::Mat& previous_background,
                               const Eigen::Matrix3d& current_from_previous, int margin_px, const ImageArea& area) {
  if (current_gray.type() != CV_8UC1 || mask.type() != CV_8UC1 || mask.size() != current_gray.size())
    throw InputError("FillMaskFromBackground: the image and the mask must be CV_8UC1 of the same size");
  if (margin_px < 0) throw InputError("FillMaskFromBackground: margin_px must be >= 0");
  if (!previous_background.empty() && previous_background.type() != CV_8UC1)
    throw InputError("FillMaskFromBackground: the previous background must be CV_8UC1");
  if (cv::countNonZero(mask) == 0) return current_gray;
  cv::Mat filled = current_gray.clone();
  if (previous_background.empty()) return filled;
  cv::Mat region = mask.clone();
  if (margin_px > 0) DilateMask(MorphShape::kRect, 2 * margin_px + 1, 1, &region);
  // Only the pixels of the grown mask are replaced: the warp covers its bounding box alone.
  const cv::Rect box = cv::boundingRect(region);
  CompensatedImage carried;
  CompensateMotionInBox(previous_background, current_from_previous, current_gray.size(), box, &carried, area);
  cv::Mat filled_box = filled(box);
  carried.image.copyTo(filled_box, region(box) & carried.valid);
  return filled;
}

}  // namespace dynvo
