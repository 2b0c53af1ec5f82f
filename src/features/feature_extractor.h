#pragma once
// ORB extraction spread over the image (ORB-SLAM quadtree), undistortion and back-projection.

#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>

#include "core/camera.h"
#include "features/feature_options.h"
#include "features/frame_features.h"

namespace dynvo {

// Per pyramid level: FAST corners at `fast_threshold`, retried at `min_fast_threshold` in
// 32-pixel cells that have none; the level's share of `num_features` (geometric in the scale)
// chosen by `distribution` (quadtree: ORB-SLAM's); intensity-centroid angle; descriptors by
// cv::ORB::compute on the level image. Corners stay 19 pixels from each level's border.
// Holds reusable buffers (pyramid, descriptor engines); no global state. Not thread-safe:
// use one extractor per thread.
class FeatureExtractor {
 public:
  // Throws InputError when `options` fail Check().
  explicit FeatureExtractor(const FeatureOptions& options);

  // ORB features of a grey image spread by `options.distribution`, undistorted with `camera`
  // when it has distortion, and back-projected through `depth` (CV_32FC1 metres, same size;
  // empty -> no depth). Optional `exclude` mask (CV_8UC1, non-zero = do not detect there) may
  // be empty. Throws InputError on wrong types or sizes.
  FrameFeatures Extract(const cv::Mat& gray, const cv::Mat& depth, const Camera& camera,
                        const cv::Mat& exclude = cv::Mat());

  const FeatureOptions& options() const { return options_; }

 private:
  // Keypoints (level-0 coordinates) and descriptors of pyramid level `l`.
  void ExtractLevel(int l, const cv::Mat& exclude, std::vector<cv::KeyPoint>* keypoints,
                    cv::Mat* descriptors) const;

  FeatureOptions options_;
  std::vector<double> scales_;            // scale of each level relative to level 0
  std::vector<int> features_per_level_;   // share of num_features per level
  std::vector<int> umax_;                 // circular patch bounds for the orientation
  std::vector<cv::Mat> pyramid_;          // grey levels
  std::vector<cv::Ptr<cv::ORB>> orbs_;    // descriptor engine per level (cv::ORB::compute)
};

}  // namespace dynvo
