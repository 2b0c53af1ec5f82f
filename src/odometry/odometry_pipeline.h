#pragma once
// The paper's per-frame pipeline (papers/README.md §1): dynamic mask from motion-compensated
// differencing, ORB features minus those in the mask, frame-to-local-map tracking with EPnP +
// Ceres refinement, keyframes and local bundle adjustment. With the mask stage switched off
// it is the baseline, identical otherwise.

#include <deque>
#include <future>
#include <memory>
#include <vector>

#include <opencv2/core.hpp>

#include "core/camera.h"
#include "core/image_area.h"
#include "dataset/tum_dataset.h"
#include "dynamic_mask/dynamic_mask_detector.h"
#include "dynamic_mask/motion_compensation.h"
#include "ego_motion/klt_tracker.h"
#include "features/feature_extractor.h"
#include "odometry/frame_record.h"
#include "odometry/odometry_config.h"
#include "tracking/frame_tracker.h"

namespace dynvo {

// One feature of a debug frame: where it was detected, what the mask did with it, and
// whether the pose used it.
struct DebugFeature {
  enum class Status { kKept, kRemoved, kReadmitted };
  cv::Point2f pixel;               // keypoint as detected (image coordinates)
  int octave = 0;                  // ORB pyramid level
  double depth_m = 0.0;            // 0 = no usable depth
  Status status = Status::kKept;   // kept by the mask, removed, or removed and readmitted
  bool inlier = false;             // an inlier of the frame's final pose
};

// The paper's Fig. 1 / Fig. 3 panels of one frame, and its features.
struct DebugPanels {
  cv::Mat compensated;    // frame t-1 warped onto t
  cv::Mat difference;     // |t - warp(t-1)|
  cv::Mat forward_mask;   // after threshold and morphology
  cv::Mat backward_mask;  // (empty when backward detection is off)
  cv::Mat fused_mask;     // the mask that removed features: the union, trimmed with depth_trim
  cv::Mat features;       // frame t, kept features green, removed red
  cv::Mat background;     // features.refill_from_background: frame t with the mask filled from earlier frames
  cv::Mat depth_change;   // depth_change.enabled: the depth-change mask carried into frame t (255 =
                          // changed; joined to fused_mask, or with seeds_only its seeds only); empty
                          // when not computed or dropped by max_share
  cv::Mat map_occlusion;  // map_occlusion.enabled: the map occlusion carried into frame t that joined
                          // fused_mask (with seeded, only its seeded regions); empty when not computed
  cv::Mat map_occlusion_candidates;  // map_occlusion.seeded: all of the carried map occlusion, the
                                     // regions the seeding chose from
  std::vector<DebugFeature> feature_list;  // every feature of frame t: the kept ones, then
                                           // the removed ones
};

class OdometryPipeline {
 public:
  // `camera` is the camera of the images passed to Process (undistorted when the reader
  // undistorts); `image_area` the part of them with image data (TumDataset::image_area(); empty =
  // all). The config must have passed Check().
  OdometryPipeline(const Camera& camera, const OdometryConfig& config, const ImageArea& image_area = {});

  // Processes frame t and returns its record (pose always set). `next` is frame t+1 (null at the
  // end of the sequence or when it is not loaded yet): backward detection "triplet" needs it, and
  // with run.lookahead its features and mask are computed beside frame t's later steps, to be taken
  // by the next call when it is handed that same frame (same pixels in memory). The results do
  // not depend on it.
  // `truth_mask` is frame t's ground-truth mask (CV_8UC1, non-zero = dynamic), used only with
  // mask source "ground_truth" (NeedsTruthMask), where it must not be empty. Fills `debug`
  // when given. Throws InputError when a needed truth mask is missing or of the wrong type or size.
  FrameRecord Process(const RgbdFrame& frame, const RgbdFrame* next, const cv::Mat& truth_mask = cv::Mat(),
                      DebugPanels* debug = nullptr);

  // True when Process wants frame t+1 (backward detection "triplet").
  bool NeedsNextFrame() const;
  // True when Process wants frame t's ground-truth mask (mask source "ground_truth").
  bool NeedsTruthMask() const;
  // True when Process uses frame t+1, given, to look ahead (run.lookahead, the detector's reverse
  // pair or the baseline; not with the triplet or ground-truth masks, which need frame t's state).
  bool LooksAhead() const;

  // The dynamic mask of the last processed frame (empty when none was computed).
  const cv::Mat& last_mask() const { return last_mask_; }

 private:
  // True when frame t's features and mask need nothing but frames t-1 and t (not the triplet's
  // frame t+1, not a ground-truth mask): ComputeImageStages gives them, in turn or ahead.
  bool ImageStagesStandAlone() const;
  // What frame t's images alone give: its ORB features and (the detector, reverse pair) its mask.
  struct ImageStages {
    bool has_features = false;
    FrameFeatures features;
    DetectedCorners corners;  // with features.refill_reuse_corners: what the extraction detected
    double features_ms = 0.0;
    bool has_mask = false;
    DynamicMaskResult mask;
    TrackingPyramid pyramid;  // frame t's KLT pyramid (the next frame's previous one)
    double mask_ms = 0.0;
  };
  // The features of `frame` and, with the mask on, its mask against frame t-1 (`previous_gray`,
  // `previous_pyramid`), the two on two threads. Uses extractor_ and reads only the options.
  ImageStages ComputeImageStages(const RgbdFrame& frame, const cv::Mat& previous_gray,
                                 const TrackingPyramid& previous_pyramid);
  // The features part of ComputeImageStages (uses extractor_).
  ImageStages ComputeFeatures(const RgbdFrame& frame);
  // The mask part of ComputeImageStages (reads only the options).
  ImageStages ComputeMask(const RgbdFrame& frame, const cv::Mat& previous_gray,
                          const TrackingPyramid& previous_pyramid) const;
  // Moves the features part of `from` (features, corners, time) into `to`.
  static void MergeFeatures(ImageStages&& from, ImageStages* to);
  // Moves the mask part of `from` (mask, pyramid, time) into `to`.
  static void MergeMask(ImageStages&& from, ImageStages* to);
  // The look-ahead of `next` in two jobs: its mask against frame t (`gray`, previous_pyramid_),
  // started as soon as frame t's own mask is known; its features once frame t's refill has left
  // extractor_ (started last, for the same `next`).
  void StartLookAheadMask(const cv::Mat& gray, const RgbdFrame& next);
  void StartLookAheadFeatures(const RgbdFrame& next);
  // The look-ahead's result when it was started for `frame`; else waits for its jobs and returns none.
  ImageStages TakeLookAhead(const RgbdFrame& frame);

  // map_occlusion: the pixels of `frame` in front of the static map at its estimated pose
  // (empty when the frame has no depth or was not tracked).
  // With `explained`, also where the map explains the frame's depth (MapOcclusionMask).
  cv::Mat MapOcclusionOf(const RgbdFrame& frame, const TrackingResult& tracking, cv::Mat* explained = nullptr);
  // True when MapOcclusionOf gives a mask for this frame: it has depth and was tracked.
  static bool MapOcclusionPossible(const RgbdFrame& frame, const TrackingResult& tracking);

  Camera camera_;
  OdometryConfig config_;
  ImageArea image_area_;
  FeatureExtractor extractor_;
  FrameTracker tracker_;
  cv::Mat previous_gray_;
  cv::Mat last_mask_;
  cv::Mat background_gray_;  // refill_from_background: frame t-1 with its mask filled from earlier frames
  // Carried between frames by the dynamic-mask step so that no image is pyramided or tracked twice:
  TrackingPyramid previous_pyramid_;  // KLT pyramid of previous_gray_
  cv::Mat next_gray_;                 // triplet: the frame t+1 of the last call ...
  TrackingPyramid next_pyramid_;      // ... and its pyramid (frame t's pyramid when it comes back as current)
  PointTracks next_tracks_;           // triplet: the last call's t -> t+1 tracks (DynamicMaskResult::next_tracks)
  struct PastDepth {
    cv::Mat depth;            // CV_32FC1 metres
    Pose world_from_camera;   // as estimated
  };
  std::deque<PastDepth> past_depths_;  // depth_change: the last frames, oldest first
  cv::Mat pending_change_;  // depth_change: between the last frame and the one `frames` before it
                            // (computed at the end of the last call; empty when not wanted)
  cv::Mat map_explained_;   // depth_trim: where frame t-1's depth is explained by the static map
  cv::Mat occlusion_mask_;  // map_occlusion: what frame t-1 measured in front of the static map
  cv::Mat kept_occlusion_;  // map_occlusion.seeded: the regions of it frame t-1 kept (seeds for frame t)
  // Look-ahead: the jobs computing the image stages of the frame whose grey image is ahead_gray_.
  // Declared last, so that they are destroyed (their jobs waited for) before what the jobs use.
  cv::Mat ahead_gray_;
  std::future<ImageStages> ahead_mask_;
  std::future<ImageStages> ahead_features_;
};

}  // namespace dynvo
