#pragma once
// The paper's per-frame pipeline (papers/README.md §1, Fig. 5) as a short sequence of stages
// with plain data between them (pipeline/frame_packets.h): a mask source (none = the baseline,
// the paper's differencing, the ground truth), the mask refinements, the feature stage, the
// tracker (frame-to-local-map pose, keyframes), the mapper (local bundle adjustment). Work that does not
// depend on frame t's state (the next frame's features and mask) runs ahead on the executor.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/camera.h"
#include "core/executor.h"
#include "core/image_area.h"
#include "dataset/tum_dataset.h"
#include "loop/loop_closer.h"
#include "mapping/local_mapper.h"
#include "odometry/frame_record.h"
#include "odometry/odometry_config.h"
#include "pipeline/feature_stage.h"
#include "pipeline/frame_packets.h"
#include "pipeline/mask_refinement.h"
#include "pipeline/mask_source.h"
#include "tracking/frame_tracker.h"

namespace dynvo {

// One processed frame: its timing.csv row and what each stage produced (for observers).
struct ProcessedFrame {
  FrameRecord record;
  FrameOutput stages;
};

class OdometryPipeline {
 public:
  // `camera` is the camera of the images passed to Process (undistorted when the reader
  // undistorts); `image_area` the part of them with image data (TumDataset::image_area(); empty =
  // all). The config must have passed Check(). Concurrent work runs on `executor` (which must
  // outlive the pipeline); without one, everything runs in order on the calling thread. With
  // `loop_closing` (slam mode), the loop closer takes the keyframes (loop/loop_closer.h).
  OdometryPipeline(const Camera& camera, const OdometryConfig& config, const ImageArea& image_area = {},
                   Executor* executor = nullptr, const LoopClosingOptions* loop_closing = nullptr);

  // Processes frame t (pose always set). `next` is frame t+1 when loaded (null at the end): the
  // triplet's backward detection needs it, and its features and mask are started ahead on the
  // executor, to be taken by the next call when it is handed that same frame. The results do not
  // depend on it. `truth_mask` is frame t's ground-truth mask (CV_8UC1, non-zero = dynamic), used
  // only with mask source "ground_truth" (NeedsTruthMask). Throws InputError when a needed truth
  // mask is missing or of the wrong type or size.
  ProcessedFrame Process(const RgbdFrame& frame, const RgbdFrame* next, const cv::Mat& truth_mask = cv::Mat());

  // True when Process wants frame t's ground-truth mask (mask source "ground_truth").
  bool NeedsTruthMask() const { return mask_source_->NeedsTruthMask(); }
  // slam mode: waits for the loop closer's searches, closes the loops found and returns the
  // corrected trajectory of the frames processed. Call once, after the last frame. Nothing
  // (nullopt) in odometry mode.
  std::optional<LoopClosingResult> FinishLoops();
  // Slam mode: the loops the background has closed so far, without waiting (nullopt in vo mode).
  std::optional<int> LoopsClosed() const;
  // What the pipeline left out of the config and why (e.g. a detector model not found), once.
  const std::vector<std::string>& notices() const { return notices_; }

 private:
  // A local BA joined the map: the tracker and this frame's pose go on from the refined map.
  void AdoptRefinedMap(size_t frame, FrameOutput& out);

  std::unique_ptr<Executor> own_executor_;  // when none is given: no workers
  Executor& executor_;
  std::vector<std::string> notices_;
  std::unique_ptr<MaskSource> mask_source_;
  std::vector<std::unique_ptr<MaskRefinement>> refinements_;
  FeatureStage features_;
  FrameTracker tracker_;
  LocalMapper mapper_;
  std::unique_ptr<LoopCloser> loop_closer_;  // slam mode
  cv::Mat last_mask_;                        // frame t-1's final mask
};

// The timing.csv row of a processed frame.
FrameRecord MakeFrameRecord(const RgbdFrame& frame, const FrameOutput& stages);

}  // namespace dynvo
