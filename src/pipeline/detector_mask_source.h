#pragma once
// The person detector as a mask source (the second paper, IPL-SLAM): each frame's movable
// objects found by a YOLO network (detection/yolo_detector.h), each box cut to its person by
// depth (detection/person_mask.h); every person found leaves the features. Frame t+1's
// detection starts on the executor while frame t is tracked.

#include <optional>
#include <vector>

#include <opencv2/core.hpp>

#include "core/executor.h"
#include "detection/detector_options.h"
#include "detection/person_mask.h"
#include "detection/yolo_detector.h"
#include "pipeline/frame_motion.h"
#include "pipeline/mask_source.h"

namespace dynvo {

class DetectorMaskSource : public MaskSource {
 public:
  // Loads the model (throws InputError naming the file when it cannot). With `estimate_motion`,
  // each packet also carries the homography frame t-1 -> t. `executor` must outlive the source.
  DetectorMaskSource(const DetectorOptions& detector, const KltOptions& klt, const HomographyOptions& homography,
                     bool estimate_motion, Executor& executor);

  // kDetected: the people's boxes and the union of their masks (empty mask: nobody).
  MaskPacket Compute(const MaskSourceInput& input) override;
  void LookAhead(const RgbdFrame& current, const RgbdFrame& next) override;

 private:
  struct People {
    std::vector<Detection> boxes;
    cv::Mat mask;  // CV_8UC1, 255 = a person
    double ms = 0.0;
  };
  // Detects a frame's people and cuts their masks by depth.
  People Detect(const RgbdFrame& frame);
  void Start(const RgbdFrame& frame);

  YoloDetector detector_;  // one detection at a time: a started task is waited for before the next
  PersonMaskOptions person_mask_;
  std::optional<FrameMotion> motion_;  // with estimate_motion
  Executor& executor_;
  Task<People> pending_;
  cv::Mat pending_bgr_;  // the pixels pending_ detects on
};

}  // namespace dynvo
