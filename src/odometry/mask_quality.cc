#include "odometry/mask_quality.h"

#include <opencv2/core.hpp>

#include "core/error.h"

namespace dynvo {

MaskCounts& MaskCounts::operator+=(const MaskCounts& o) {
  true_positive += o.true_positive;
  false_positive += o.false_positive;
  false_negative += o.false_negative;
  return *this;
}

double MaskCounts::Precision() const {
  const long long d = true_positive + false_positive;
  return d == 0 ? 1.0 : static_cast<double>(true_positive) / d;
}

double MaskCounts::Recall() const {
  const long long d = true_positive + false_negative;
  return d == 0 ? 1.0 : static_cast<double>(true_positive) / d;
}

double MaskCounts::Iou() const {
  const long long d = true_positive + false_positive + false_negative;
  return d == 0 ? 1.0 : static_cast<double>(true_positive) / d;
}

MaskCounts CompareMasks(const cv::Mat& detected, const cv::Mat& truth) {
  CV_Assert(truth.type() == CV_8UC1);
  MaskCounts counts;
  if (detected.empty()) {
    counts.false_negative = cv::countNonZero(truth);
    return counts;
  }
  CV_Assert(detected.type() == CV_8UC1 && detected.size() == truth.size());
  for (int y = 0; y < truth.rows; ++y) {
    const uchar* d = detected.ptr<uchar>(y);
    const uchar* t = truth.ptr<uchar>(y);
    for (int x = 0; x < truth.cols; ++x) {
      const bool dd = d[x] != 0, tt = t[x] != 0;
      counts.true_positive += dd && tt;
      counts.false_positive += dd && !tt;
      counts.false_negative += !dd && tt;
    }
  }
  return counts;
}

StillFeatureCounts& StillFeatureCounts::operator+=(const StillFeatureCounts& o) {
  detected += o.detected;
  kept += o.kept;
  return *this;
}

double StillFeatureCounts::KeptShare() const { return detected == 0 ? 1.0 : static_cast<double>(kept) / detected; }

StillFeatureCounts CountStillFeatures(const FeatureSplit& split, const cv::Mat& still) {
  CV_Assert(still.type() == CV_8UC1);
  const auto on_still = [&still](const std::vector<cv::KeyPoint>& keypoints) {
    long long n = 0;
    for (const cv::KeyPoint& k : keypoints) {
      const cv::Point p(cvRound(k.pt.x), cvRound(k.pt.y));
      n += p.inside(cv::Rect(0, 0, still.cols, still.rows)) && still.at<uchar>(p) != 0;
    }
    return n;
  };
  StillFeatureCounts counts;
  counts.kept = on_still(split.kept.keypoints);
  counts.detected = counts.kept + on_still(split.removed.keypoints);
  return counts;
}

}  // namespace dynvo
