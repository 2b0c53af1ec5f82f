#include "dynamic_mask/depth_trim.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "core/error.h"

namespace dynvo {

void DepthTrimOptions::Check() const {
  const std::string section = "depth_trim";
  RequireOption(std::isfinite(min_gap) && min_gap > 0.0, section, "min_gap", "> 0", min_gap);
  RequireOption(min_region_px >= 1, section, "min_region_px", ">= 1", min_region_px);
  RequireOption(std::isfinite(min_explained) && min_explained >= 0.0 && min_explained <= 1.0, section, "min_explained",
                "in [0, 1]", min_explained);
}

namespace {

constexpr int kBins = 64;

// Otsu's threshold (a bin index: bins <= it are the lower class) of a histogram; -1 when one
// class would be empty.
int OtsuBin(const std::array<double, kBins>& histogram) {
  double total = 0.0, weighted = 0.0;
  for (int i = 0; i < kBins; ++i) {
    total += histogram[i];
    weighted += i * histogram[i];
  }
  double below = 0.0, below_weighted = 0.0, best = -1.0;
  int best_bin = -1;
  for (int i = 0; i < kBins - 1; ++i) {
    below += histogram[i];
    below_weighted += i * histogram[i];
    const double above = total - below;
    if (below <= 0.0 || above <= 0.0) continue;
    const double difference = below_weighted / below - (weighted - below_weighted) / above;
    const double between = below * above * difference * difference;
    if (between > best) {
      best = between;
      best_bin = i;
    }
  }
  return best_bin;
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
  cv::Mat labels, stats, centroids;
  const int regions = cv::connectedComponentsWithStats(trimmed, labels, stats, centroids, 8, CV_32S);
  for (int r = 1; r < regions; ++r) {
    if (stats.at<int>(r, cv::CC_STAT_AREA) < options.min_region_px) continue;
    const cv::Rect box(stats.at<int>(r, cv::CC_STAT_LEFT), stats.at<int>(r, cv::CC_STAT_TOP),
                       stats.at<int>(r, cv::CC_STAT_WIDTH), stats.at<int>(r, cv::CC_STAT_HEIGHT));
    std::vector<float> logs;
    float low = std::numeric_limits<float>::max(), high = std::numeric_limits<float>::lowest();
    for (int y = box.y; y < box.y + box.height; ++y)
      for (int x = box.x; x < box.x + box.width; ++x) {
        const float z = depth.at<float>(y, x);
        if (labels.at<int>(y, x) != r || z <= 0.0f) continue;
        const float l = std::log(z);
        logs.push_back(l);
        low = std::min(low, l);
        high = std::max(high, l);
      }
    if (logs.size() < 2 || !(high > low)) continue;
    const float bin_width = (high - low) / kBins;
    auto bin_of = [&](float l) { return std::min(kBins - 1, static_cast<int>((l - low) / bin_width)); };
    std::array<double, kBins> histogram{};
    for (float l : logs) histogram[bin_of(l)] += 1.0;
    const int split = OtsuBin(histogram);
    if (split < 0) continue;
    double near_sum = 0.0, far_sum = 0.0;
    int near_count = 0, far_count = 0;
    for (float l : logs) {
      if (bin_of(l) <= split) {
        near_sum += std::exp(l);
        ++near_count;
      } else {
        far_sum += std::exp(l);
        ++far_count;
      }
    }
    if (near_count == 0 || far_count == 0) continue;
    if (far_sum / far_count <= (1.0 + options.min_gap) * (near_sum / near_count)) continue;
    // The farther group's pixels, and how many of them the map explains.
    auto in_far_group = [&](int x, int y) {
      const float z = depth.at<float>(y, x);
      return labels.at<int>(y, x) == r && z > 0.0f && bin_of(std::log(z)) > split;
    };
    int far_explained = 0;
    for (int y = box.y; y < box.y + box.height; ++y)
      for (int x = box.x; x < box.x + box.width; ++x)
        if (in_far_group(x, y) && explained.at<uint8_t>(y, x)) ++far_explained;
    if (far_explained < options.min_explained * far_count) continue;
    for (int y = box.y; y < box.y + box.height; ++y)
      for (int x = box.x; x < box.x + box.width; ++x)
        if (in_far_group(x, y)) trimmed.at<uint8_t>(y, x) = 0;
  }
  return trimmed;
}

}  // namespace dynvo
