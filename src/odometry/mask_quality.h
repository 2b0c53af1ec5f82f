#pragma once
// Agreement of a detected dynamic mask with a ground-truth one, pixel by pixel, and what it left
// of the features on people who are not moving.

#include <opencv2/core.hpp>

#include "features/feature_filter.h"

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

// The features detected on people who are not moving, and those of them the mask left to the pose.
struct StillFeatureCounts {
  long long detected = 0;
  long long kept = 0;

  StillFeatureCounts& operator+=(const StillFeatureCounts& o);
  // kept / detected; 1 when none was detected.
  double KeptShare() const;
};

// The features of `split` (kept and removed, at their detected positions) on the non-zero pixels
// of `still` (CV_8UC1, same size as the mask that split them). After a refill the kept ones come
// from the refill: those on `still` count as kept and as detected.
StillFeatureCounts CountStillFeatures(const FeatureSplit& split, const cv::Mat& still);

}  // namespace dynvo
