#pragma once
// Agreement of a detected dynamic mask with a ground-truth one, pixel by pixel.

#include <opencv2/core.hpp>

namespace dynvo {

struct MaskCounts {
  long long true_positive = 0;   // detected and truly dynamic
  long long false_positive = 0;  // detected, truly static
  long long false_negative = 0;  // missed dynamic pixel

  MaskCounts& operator+=(const MaskCounts& o);
  // TP / (TP + FP); 1 when nothing was detected (no false alarm).
  double Precision() const;
  // TP / (TP + FN); 1 when nothing was dynamic.
  double Recall() const;
  // TP / (TP + FP + FN); 1 when both masks are empty.
  double Iou() const;
};

// Counts over all pixels; non-zero means dynamic in both masks (CV_8UC1, same size). An empty
// `detected` counts as all static.
MaskCounts CompareMasks(const cv::Mat& detected, const cv::Mat& truth);

}  // namespace dynvo
