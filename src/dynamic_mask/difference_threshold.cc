#include "dynamic_mask/difference_threshold.h"

#include <algorithm>
#include <array>

#include <opencv2/imgproc.hpp>

#include "core/error.h"

namespace dynvo {

namespace {

// Otsu's threshold of a 256-bin histogram (CV_32F counts, as cv::calcHist writes it).
int OtsuOfHistogram(const cv::Mat& histogram) {
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

cv::Mat Histogram(const cv::Mat& image, const cv::Mat& mask) {
  cv::Mat histogram;
  const int channels[] = {0};
  const int bins[] = {256};
  const float range[] = {0.0f, 256.0f};
  const float* ranges[] = {range};
  cv::calcHist(&image, 1, channels, mask, histogram, 1, bins, ranges);
  return histogram;
}

void CheckOtsuInput(const cv::Mat& image, const cv::Mat& valid) {
  if (image.type() != CV_8UC1 || image.empty()) throw InputError("OtsuThreshold needs a non-empty CV_8UC1 image");
  if (!valid.empty() && (valid.type() != CV_8UC1 || valid.size() != image.size()))
    throw InputError("OtsuThreshold: valid mask must be CV_8UC1 of the image size");
}

}  // namespace

int OtsuThreshold(const cv::Mat& image, const cv::Mat& valid) {
  CheckOtsuInput(image, valid);
  return OtsuOfHistogram(Histogram(image, valid));
}

int OtsuThresholdZeroOutsideValid(const cv::Mat& image, const cv::Mat& valid) {
  CheckOtsuInput(image, valid);
  // An unmasked histogram is about twice as fast as a masked one; the invalid pixels all sit in bin 0.
  cv::Mat histogram = Histogram(image, cv::Mat());
  if (!valid.empty()) {
    const int invalid = static_cast<int>(valid.total()) - cv::countNonZero(valid);
    histogram.at<float>(0) = std::max(0.0f, histogram.at<float>(0) - static_cast<float>(invalid));
  }
  return OtsuOfHistogram(histogram);
}

int DifferenceThreshold(const cv::Mat& difference, const cv::Mat& valid, const DynamicMaskOptions& options) {
  if (options.threshold == ThresholdMethod::kFixed) return options.fixed_threshold;
  return std::max(OtsuThresholdZeroOutsideValid(difference, valid), options.min_otsu_threshold);
}

void Binarize(const cv::Mat& image, int threshold, cv::Mat* binary) {
  if (image.type() != CV_8UC1) throw InputError("Binarize needs a CV_8UC1 image");
  cv::threshold(image, *binary, threshold, 255, cv::THRESH_BINARY);
}

}  // namespace dynvo
