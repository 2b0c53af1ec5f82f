#include "dynamic_mask/mask_regions.h"

#include <cmath>

#include <opencv2/imgproc.hpp>

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

cv::Mat MaskUnion(const cv::Mat& a, const cv::Mat& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return a | b;
}

cv::Mat RegionsTouching(const cv::Mat& regions, const cv::Mat& seeds) {
  if (regions.type() != CV_8UC1) throw InputError("RegionsTouching needs a CV_8UC1 regions mask");
  cv::Mat kept = cv::Mat::zeros(regions.size(), CV_8UC1);
  if (seeds.empty() || regions.empty()) return kept;
  if (seeds.type() != CV_8UC1 || seeds.size() != regions.size())
    throw InputError("RegionsTouching needs CV_8UC1 seeds of the regions' size");
  // Every region lies inside the bounding box of the non-zero pixels: label that box alone.
  const cv::Rect box = cv::boundingRect(regions);
  if (box.area() == 0) return kept;
  const cv::Mat regions_box = regions(box), seeds_box = seeds(box);
  cv::Mat labels;
  const int count = cv::connectedComponents(regions_box, labels, 8, CV_32S);
  std::vector<uint8_t> touched(static_cast<size_t>(count), 0);
  for (int y = 0; y < box.height; ++y) {
    const uint8_t* region = regions_box.ptr<uint8_t>(y);
    const uint8_t* seed = seeds_box.ptr<uint8_t>(y);
    const int* label = labels.ptr<int>(y);
    for (int x = 0; x < box.width; ++x)
      if (region[x] && seed[x]) touched[static_cast<size_t>(label[x])] = 1;
  }
  cv::Mat kept_box = kept(box);
  for (int y = 0; y < box.height; ++y) {
    const int* label = labels.ptr<int>(y);
    uint8_t* out = kept_box.ptr<uint8_t>(y);
    for (int x = 0; x < box.width; ++x)
      if (label[x] > 0 && touched[static_cast<size_t>(label[x])]) out[x] = 255;
  }
  return kept;
}

}  // namespace dynvo
