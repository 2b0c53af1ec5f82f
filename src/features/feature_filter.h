#pragma once
// Splitting frame features by a mask (e.g. the dynamic-object mask).

#include <vector>

#include <opencv2/core.hpp>

#include "features/frame_features.h"

namespace dynvo {

// Features on non-zero `mask` pixels (removed) and the rest (kept), in their original order.
struct FeatureSplit {
  FrameFeatures kept;
  FrameFeatures removed;
  std::vector<int> kept_indices;     // index in the input of each kept feature (empty after a
                                     // refill: the kept ones then come from another extraction)
  std::vector<int> removed_indices;  // index in the input of each removed feature
};

// Splits `features` by the keypoint position (rounded, as detected) in `mask` (CV_8UC1);
// keypoints outside the mask image are kept. An empty mask keeps everything. Throws
// InputError when the mask is not CV_8UC1.
FeatureSplit SplitByMask(const FrameFeatures& features, const cv::Mat& mask);

// The features at `indices`, in that order.
FrameFeatures SelectFeatures(const FrameFeatures& features, const std::vector<int>& indices);

// Appends all of `from` after the features of `to`. Throws InputError when the descriptors of
// both are non-empty with different widths or types.
void AppendFeatures(const FrameFeatures& from, FrameFeatures* to);

}  // namespace dynvo
