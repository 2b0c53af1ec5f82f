#include "dynamic_mask/mask_regions.h"

#include <cmath>

#include "core/error.h"

namespace dynvo {

bool InMaskRegion(const cv::Mat& mask, const cv::Point2f& point) {
  if (mask.empty()) return false;
  if (mask.type() != CV_8UC1) throw InputError("InMaskRegion needs a CV_8UC1 mask");
  const int x = static_cast<int>(std::lround(point.x));
  const int y = static_cast<int>(std::lround(point.y));
  if (x < 0 || y < 0 || x >= mask.cols || y >= mask.rows) return false;
  return mask.at<uint8_t>(y, x) != 0;
}

std::vector<uint8_t> StaticPointFlags(const cv::Mat& mask, const std::vector<cv::Point2f>& points) {
  std::vector<uint8_t> flags(points.size(), 1);
  for (size_t i = 0; i < points.size(); ++i) flags[i] = InMaskRegion(mask, points[i]) ? 0 : 1;
  return flags;
}

}  // namespace dynvo
