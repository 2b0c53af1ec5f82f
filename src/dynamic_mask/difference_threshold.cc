#include "dynamic_mask/difference_threshold.h"

#include <algorithm>
#include <array>

#include <opencv2/imgproc.hpp>

#include "core/error.h"

namespace dynvo {

int OtsuThreshold(const cv::Mat& image, const cv::Mat& valid) {
  if (image.type() != CV_8UC1 || image.empty()) throw InputError("OtsuThreshold needs a non-empty CV_8UC1 image");
  if (!valid.empty() && (valid.type() != CV_8UC1 || valid.size() != image.size()))
    throw InputError("OtsuThreshold: valid mask must be CV_8UC1 of the image size");
  cv::Mat histogram;
  const int channels[] = {0};
  const int bins[] = {256};
  const float range[] = {0.0f, 256.0f};
  const float* ranges[] = {range};
  cv::calcHist(&image, 1, channels, valid, histogram, 1, bins, ranges);

  double total = 0.0, weighted_total = 0.0;
  for (int i = 0; i < 256; ++i) {
    const double count = histogram.at<float>(i);
    total += count;
    weighted_total += i * count;
  }
  if (total <= 0.0) return 0;
  int best = 0;
  double best_variance = 0.0;
  double below = 0.0, weighted_below = 0.0;
  for (int t = 0; t < 255; ++t) {
    const double count = histogram.at<float>(t);
    below += count;
    weighted_below += t * count;
    const double above = total - below;
    if (below <= 0.0 || above <= 0.0) continue;
    const double mean_below = weighted_below / below;
    const double mean_above = (weighted_total - weighted_below) / above;
    const double variance = below * above * (mean_below - mean_above) * (mean_below - mean_above);
    if (variance > best_variance) {
      best_variance = variance;
      best = t;
    }
  }
  return best;
}

int DifferenceThreshold(const cv::Mat& difference, const cv::Mat& valid, const DynamicMaskOptions& options) {
  if (options.threshold == ThresholdMethod::kFixed) return options.fixed_threshold;
  return std::max(OtsuThreshold(difference, valid), options.min_otsu_threshold);
}

void Binarize(const cv::Mat& image, int threshold, cv::Mat* binary) {
  if (image.type() != CV_8UC1) throw InputError("Binarize needs a CV_8UC1 image");
  cv::threshold(image, *binary, threshold, 255, cv::THRESH_BINARY);
}

}  // namespace dynvo
