#pragma once
// The third stage of the pipeline: frame t's ORB features (extracted on the executor beside the
// mask, or ahead while frame t-1 was finished), split by the mask, and its line segments off the
// mask when lines are on; with refill_outside_mask the
// budget the mask took is spent again off the mask and its margin, optionally chosen among the
// frame's own corners and described on the static background seen there before.

#include "core/camera.h"
#include "core/executor.h"
#include "core/image_area.h"
#include "dataset/tum_dataset.h"
#include "features/extractor_pool.h"
#include "pipeline/frame_packets.h"

namespace dynvo {

class FeatureStage {
 public:
  // `options` must have passed Check(); `executor` must outlive the stage.
  FeatureStage(const Camera& camera, const FeatureOptions& options, const ImageArea& image_area, Executor& executor);

  // Frame t's extraction is under way: taken from the look-ahead when that was started for
  // the same frame (same pixels in memory), else started now on the executor.
  void Begin(const RgbdFrame& frame);
  // Frame t's features split by `mask` (then refilled); waits for the extraction Begin started.
  // Rethrows the extraction's error (InputError on bad images).
  FeaturePacket Finish(const RgbdFrame& frame, const MaskPacket& mask);
  // Starts frame t+1's extraction on the executor, for the next Begin.
  void LookAhead(const RgbdFrame& next);

 private:
  struct Extraction {
    FrameFeatures features;
    DetectedCorners corners;  // with refill_reuse_corners: what the extraction detected
    double ms = 0.0;
  };
  struct LineDetection {
    FrameLines lines;
    double ms = 0.0;
  };
  void Start(const RgbdFrame& frame);
  // Spends the budget the mask took off the mask grown by the margin, on `described`.
  FrameFeatures Refill(const RgbdFrame& frame, const cv::Mat& mask, const cv::Mat& described,
                       const DetectedCorners& corners);

  Camera camera_;
  FeatureOptions options_;
  ImageArea image_area_;
  Executor& executor_;
  ExtractorPool extractors_;
  cv::Mat background_gray_;  // refill_from_background: frame t-1 with its mask filled from earlier frames
  // The extraction under way, of the frame whose grey image is pending_gray_ (declared last).
  cv::Mat pending_gray_;
  Task<Extraction> pending_;
  Task<LineDetection> pending_lines_;  // features.lines.enabled: its own task, beside the ORB one
};

}  // namespace dynvo
