#pragma once
// ORB extraction spread over the image (ORB-SLAM quadtree), undistortion and back-projection.

#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>

#include "core/camera.h"
#include "core/executor.h"
#include "features/feature_options.h"
#include "features/frame_features.h"

namespace dynvo {

// What one extraction described on one pyramid level: ExtractFromCorners takes a keypoint's
// angle and descriptor from here where the image it describes equals this one around it.
struct DescribedLevel {
  cv::Mat image;              // the level's grey image (never written into afterwards)
  std::vector<int> row;       // per detected corner of the level: its row below; -1 = not chosen
  std::vector<float> angles;  // per row: the keypoint's angle (degrees)
  cv::Mat descriptors;        // one row per chosen corner
};

// The corners one extraction detected, per pyramid level, before they were spread and
// described: what FeatureExtractor::ExtractFromCorners chooses from again.
struct DetectedCorners {
  cv::Size image_size;                            // of the image they were detected on
  std::vector<std::vector<cv::KeyPoint>> levels;  // per level, level pixel coordinates
  std::vector<DescribedLevel> described;          // per level; empty = nothing to reuse

  bool empty() const { return levels.empty(); }
};

// Per pyramid level: FAST corners at `fast_threshold`, retried at `min_fast_threshold` in
// 32-pixel cells that have none; the level's share of `num_features` (geometric in the scale)
// chosen by `distribution` (quadtree: ORB-SLAM's); intensity-centroid angle; descriptors by
// cv::ORB::compute on the level image. Corners stay 19 pixels from each level's border.
// Holds reusable buffers (pyramid, descriptor engines); no global state. Not thread-safe:
// use one extractor per concurrent job (features/extractor_pool.h).
class FeatureExtractor {
 public:
  // Throws InputError when `options` fail Check(). With `levels_executor` (which must outlive
  // the extractor), the pyramid levels are detected and described on it (same result).
  explicit FeatureExtractor(const FeatureOptions& options, Executor* levels_executor = nullptr);

  // ORB features of a grey image spread by `options.distribution`, undistorted with `camera`
  // when it has distortion, and back-projected through `depth` (CV_32FC1 metres, same size;
  // empty -> no depth). Optional `exclude` mask (CV_8UC1, non-zero = do not detect there) may
  // be empty. Throws InputError on wrong types or sizes.
  // With `corners`, also the corners detected (before spreading), for ExtractFromCorners.
  FrameFeatures Extract(const cv::Mat& gray, const cv::Mat& depth, const Camera& camera,
                        const cv::Mat& exclude = cv::Mat(), DetectedCorners* corners = nullptr);

  // Features chosen again from corners an earlier Extract detected: those off `exclude` (same
  // rules as Extract's), spread by `options.distribution`, oriented and described on `gray` (the
  // image they were detected on, or one that differs from it only where the caller knows, e.g.
  // filled from the background). No detection pass: corners Extract would have found by
  // retrying cells whose corners are all excluded are not found. With corners of the same image
  // and an empty `exclude`, equals Extract. A keypoint Extract described, whose patch and blur
  // see the same pixels in `gray` as in the image Extract described, keeps its angle and
  // descriptor (the same values, not computed again). Throws InputError on wrong types or sizes,
  // or when `corners` were detected at another image size or pyramid depth.
  FrameFeatures ExtractFromCorners(const DetectedCorners& corners, const cv::Mat& gray, const cv::Mat& depth,
                                   const Camera& camera, const cv::Mat& exclude = cv::Mat());

  const FeatureOptions& options() const { return options_; }

 private:
  // True when level `l` is large enough and has a share of the features.
  bool LevelUsable(int l) const;
  // Corners of pyramid level `l` off `exclude` (level coordinates, unspread).
  void DetectLevel(int l, const cv::Mat& exclude, std::vector<cv::KeyPoint>* candidates) const;
  // Indices into `candidates` of level `l`'s share of the features, by options_.distribution.
  std::vector<int> ChooseOnLevel(int l, const std::vector<cv::KeyPoint>& candidates) const;
  // Keypoints (level-0 coordinates) and descriptors of pyramid level `l` from its candidates.
  // With `earlier` (and `earlier_index`: each candidate's index among its corners), angles and
  // descriptors are taken from it where the level's pixels around the keypoint are unchanged.
  // With `record`, what was described is kept there.
  void DescribeLevel(int l, const std::vector<cv::KeyPoint>& candidates, const DescribedLevel* earlier,
                     const std::vector<int>* earlier_index, std::vector<cv::KeyPoint>* keypoints, cv::Mat* descriptors,
                     DescribedLevel* record) const;
  // Descriptors of `keypoints[i]` (level coordinates, angles set) for each i of `fresh`, into
  // `descriptors` row i: cv::ORB::compute on the part of level `l` around them.
  void ComputeDescriptors(int l, const std::vector<cv::KeyPoint>& keypoints, const std::vector<int>& fresh,
                          cv::Mat* descriptors) const;
  // The pyramid of `gray` into pyramid_ (after checking the inputs).
  void BuildPyramid(const cv::Mat& gray, const cv::Mat& depth, const cv::Mat& exclude);
  // Runs `per_level(l)` for every level (on levels_executor_ when given).
  template <typename PerLevel>
  void ForEachLevel(const PerLevel& per_level) const;
  // The features of the levels' keypoints and descriptors: undistorted, back-projected.
  FrameFeatures Assemble(const std::vector<std::vector<cv::KeyPoint>>& level_keypoints,
                         const std::vector<cv::Mat>& level_descriptors, const cv::Mat& depth,
                         const Camera& camera) const;

  FeatureOptions options_;
  Executor* levels_executor_ = nullptr;
  std::vector<double> scales_;           // scale of each level relative to level 0
  std::vector<int> features_per_level_;  // share of num_features per level
  std::vector<int> umax_;                // circular patch bounds for the orientation
  std::vector<cv::Mat> pyramid_;         // grey levels
  std::vector<cv::Ptr<cv::ORB>> orbs_;   // descriptor engine per level (cv::ORB::compute)
};

}  // namespace dynvo
