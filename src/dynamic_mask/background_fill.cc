#include "dynamic_mask/background_fill.h"

#include "core/error.h"
#include "dynamic_mask/mask_morphology.h"

namespace dynvo {

cv::Mat FillMaskFromBackground(const cv::Mat& current_gray, const cv::Mat& mask, const cv::Mat& previous_background,
                               const Eigen::Matrix3d& current_from_previous, int margin_px, const ImageArea& area) {
  CompensatedImage carried;  // stays empty when there is nothing to fill or nothing to fill it from
  if (!previous_background.empty()) {
    if (previous_background.type() != CV_8UC1)
      throw InputError("FillMaskFromBackground: the previous background must be CV_8UC1");
    if (mask.type() == CV_8UC1 && cv::countNonZero(mask) > 0)
      CompensateMotion(previous_background, current_from_previous, current_gray.size(), &carried, area);
  }
  return FillMaskFromCarriedBackground(current_gray, mask, carried, margin_px);
}

cv::Mat FillMaskFromCarriedBackground(const cv::Mat& current_gray, const cv::Mat& mask, const CompensatedImage& carried,
                                      int margin_px) {
  if (current_gray.type() != CV_8UC1 || mask.type() != CV_8UC1 || mask.size() != current_gray.size())
    throw InputError("FillMaskFromBackground: the image and the mask must be CV_8UC1 of the same size");
  if (margin_px < 0) throw InputError("FillMaskFromBackground: margin_px must be >= 0");
  if (cv::countNonZero(mask) == 0) return current_gray;
  cv::Mat filled = current_gray.clone();
  if (carried.image.empty()) return filled;
  if (carried.image.type() != CV_8UC1 || carried.image.size() != current_gray.size() ||
      carried.valid.type() != CV_8UC1 || carried.valid.size() != current_gray.size())
    throw InputError("FillMaskFromBackground: the carried background must be CV_8UC1 of the image's size, with its valid mask");
  cv::Mat region = mask.clone();
  if (margin_px > 0) DilateMask(MorphShape::kRect, 2 * margin_px + 1, 1, &region);
  carried.image.copyTo(filled, region & carried.valid);
  return filled;
}

}  // namespace dynvo
