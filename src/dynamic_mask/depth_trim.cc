#include "dynamic_mask/depth_trim.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "core/config_registry.h"
#include "core/error.h"
#include "dynamic_mask/difference_threshold.h"

namespace dynvo {

void DepthTrimOptions::Check() const {
  const std::string section = "depth_trim";
  RequireOption(std::isfinite(min_gap) && min_gap > 0.0, section, "min_gap", "> 0", min_gap);
  RequireOption(min_region_px >= 1, section, "min_region_px", ">= 1", min_region_px);
  RequireOption(std::isfinite(min_explained) && min_explained >= 0.0 && min_explained <= 1.0, section, "min_explained",
                "in [0, 1]", min_explained);
}

namespace {

constexpr int kBins = 64;  // levels of log depth Otsu's threshold chooses from

// The log depths of region `r`'s pixels inside `box` (labels at `box` shifted by
// `label_offset`), quantised to kBins levels over their range: `level` (CV_8UC1, 0 outside the
// region) and `in_region` (255 where the region has depth). False when the region has no
// pixel with depth, or only one depth.
bool QuantiseRegionDepth(const cv::Mat& depth, const cv::Mat& labels, int r, const cv::Rect& box,
                         const cv::Point& label_offset, cv::Mat* in_region, cv::Mat* level) {
  cv::Mat log_depth(box.size(), CV_32FC1, cv::Scalar(0.0f));
  *in_region = cv::Mat::zeros(box.size(), CV_8UC1);
  float low = std::numeric_limits<float>::max(), high = std::numeric_limits<float>::lowest();
  for (int y = 0; y < box.height; ++y) {
    const float* z = depth.ptr<float>(box.y + y) + box.x;
    const int* label = labels.ptr<int>(label_offset.y + y) + label_offset.x;
    float* log_row = log_depth.ptr<float>(y);
    uint8_t* in_row = in_region->ptr<uint8_t>(y);
    for (int x = 0; x < box.width; ++x) {
      if (label[x] != r || z[x] <= 0.0f) continue;
      const float l = std::log(z[x]);
      log_row[x] = l;
      in_row[x] = 255;
      low = std::min(low, l);
      high = std::max(high, l);
    }
  }
  if (!(high > low)) return false;
  const float level_width = (high - low) / kBins;
  *level = cv::Mat::zeros(box.size(), CV_8UC1);
  for (int y = 0; y < box.height; ++y) {
    const float* log_row = log_depth.ptr<float>(y);
    const uint8_t* in_row = in_region->ptr<uint8_t>(y);
    uint8_t* level_row = level->ptr<uint8_t>(y);
    for (int x = 0; x < box.width; ++x)
      if (in_row[x])
        level_row[x] = static_cast<uint8_t>(std::min(kBins - 1, static_cast<int>((log_row[x] - low) / level_width)));
  }
  return true;
}

}  // namespace

cv::Mat TrimMaskToNearSurface(const cv::Mat& mask, const cv::Mat& depth, const cv::Mat& explained,
                              const DepthTrimOptions& options) {
  options.Check();
  if (depth.empty() || depth.type() != CV_32FC1)
    throw InputError("TrimMaskToNearSurface: depth must be a non-empty CV_32FC1 image");
  if (mask.type() != CV_8UC1 || mask.size() != depth.size())
    throw InputError("TrimMaskToNearSurface: mask must be CV_8UC1 of the depth image's size");
  if (explained.type() != CV_8UC1 || explained.size() != depth.size())
    throw InputError("TrimMaskToNearSurface: explained must be CV_8UC1 of the depth image's size");
  cv::Mat trimmed = (mask != 0);
  // Every region lies inside the bounding box of the mask: label that box alone.
  const cv::Rect mask_box = cv::boundingRect(trimmed);
  if (mask_box.area() == 0) return trimmed;
  cv::Mat labels, stats, centroids;  // of mask_box's pixels
  const int regions = cv::connectedComponentsWithStats(trimmed(mask_box), labels, stats, centroids, 8, CV_32S);
  for (int r = 1; r < regions; ++r) {
    if (stats.at<int>(r, cv::CC_STAT_AREA) < options.min_region_px) continue;
    const cv::Rect box(mask_box.x + stats.at<int>(r, cv::CC_STAT_LEFT), mask_box.y + stats.at<int>(r, cv::CC_STAT_TOP),
                       stats.at<int>(r, cv::CC_STAT_WIDTH), stats.at<int>(r, cv::CC_STAT_HEIGHT));
    cv::Mat in_region, level;  // region pixels with depth; their log-depth levels
    if (!QuantiseRegionDepth(depth, labels, r, box, box.tl() - mask_box.tl(), &in_region, &level)) continue;
    const int split = OtsuThresholdZeroOutsideValid(level, in_region);  // levels above it are the farther group
    // The two groups' mean depths, and how much of the farther group the map explains.
    double near_sum = 0.0, far_sum = 0.0;
    int near_count = 0, far_count = 0, far_explained = 0;
    for (int y = 0; y < box.height; ++y) {
      const float* z = depth.ptr<float>(box.y + y) + box.x;
      const uint8_t* explained_row = explained.ptr<uint8_t>(box.y + y) + box.x;
      const uint8_t* in_row = in_region.ptr<uint8_t>(y);
      const uint8_t* level_row = level.ptr<uint8_t>(y);
      for (int x = 0; x < box.width; ++x) {
        if (!in_row[x]) continue;
        if (level_row[x] > split) {
          far_sum += z[x];
          ++far_count;
          if (explained_row[x]) ++far_explained;
        } else {
          near_sum += z[x];
          ++near_count;
        }
      }
    }
    if (near_count == 0 || far_count == 0) continue;
    if (far_sum / far_count <= (1.0 + options.min_gap) * (near_sum / near_count)) continue;
    if (far_explained < options.min_explained * far_count) continue;
    for (int y = 0; y < box.height; ++y) {
      const uint8_t* in_row = in_region.ptr<uint8_t>(y);
      const uint8_t* level_row = level.ptr<uint8_t>(y);
      uint8_t* out = trimmed.ptr<uint8_t>(box.y + y) + box.x;
      for (int x = 0; x < box.width; ++x)
        if (in_row[x] && level_row[x] > split) out[x] = 0;
    }
  }
  return trimmed;
}

void BindConfigKeys(const std::string& prefix, DepthTrimOptions* o, ConfigRegistry* r) {
  r->Bind(prefix + ".enabled", &o->enabled,
          "trim each region of the mask to its near surface: where its depths fall into two groups "
          "(Otsu) and the static map explains the farther one (the background behind what moves), that "
          "one is dropped (needs map_occlusion.enabled)");
}

}  // namespace dynvo
